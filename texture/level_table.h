// level_table.h: one value per mip level (a level's size, or where its
// texels start), looked up per lane: each lane of a sample may read its own
// level. Both samplers keep their levels' sizes and bases in these.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "simd/lane_vec.h"

namespace st::texel {

class LevelTable {
public:
    // Level size()'s value: levels are added in order, from the base.
    void push_back(int32_t value) {
        const size_t l = values_.size();
        values_.push_back(value);
        if (l < 2 * size_t(kLanes)) parts_[l / kLanes].set(int(l % kLanes), value);
    }
    int32_t operator[](size_t level) const { return values_[level]; }
    int32_t back() const { return values_.back(); }
    size_t size() const { return values_.size(); }

    // Each lane's level's value, for levels in [0, size()) on every lane.
    // Chains of at most 2 * kLanes levels (every texture up to 32768
    // texels on a side even with 8 lanes) are held as lanes, entry l in
    // part l / kLanes: one or two permutes instead of a gather (three
    // gathers a sample cost a third of a trilinear read in the relief
    // search with 16 lanes).
    ST_INLINE Int lookup(Int level) const {
        const size_t n = values_.size();
        if (n == 1) return Int(values_[0]);
        if (n <= size_t(kLanes)) return simd::permute(parts_[0], level);
        if (n <= 2 * size_t(kLanes)) return simd::permute2(parts_[0], parts_[1], level);
        return simd::gather(values_.data(), level, Mask(true));
    }

private:
    std::vector<int32_t> values_;
    Int parts_[2] = {Int(0), Int(0)};
};

}  // namespace st::texel
