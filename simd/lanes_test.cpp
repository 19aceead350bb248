// lanes_test.cpp: every lane of a lane operation computes what the scalar
// operation computes for that lane's value alone (NaN, infinities, denormals
// and out-of-range conversions included), and the few operations that look
// across lanes (masks, permutes, reductions, gathers) do what they say.
#include "simd/lanes.h"
#include "simd/lane_uint.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <xmmintrin.h>

namespace st::simd {

namespace {

uint32_t bits_of(float x) { return std::bit_cast<uint32_t>(x); }

// Floats that break things: signed zeros, denormals, NaN, infinities, the
// int32 conversion limits, and random values of every magnitude.
std::vector<float> awkward_floats() {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> v = {0.0f, -0.0f, 1e-45f, -1e-45f, 1e-39f, 0.5f, -0.5f, 1.5f, 2.5f, -2.5f, 1.0f,
                            inf, -inf, nan, -nan, 2147483520.0f, 2147483648.0f, -2147483648.0f, -2147483904.0f,
                            1e30f, -1e30f, 8388607.5f, 0.49999997f};
    std::mt19937 rng(7);
    for (int i = 0; i < 4000; ++i) {
        const uint32_t b = uint32_t(rng());
        v.push_back(std::bit_cast<float>(b));  // every exponent, NaNs included
    }
    return v;
}

// Runs op on kLanes of `values` at a time and scalar(x) on each, lane by lane.
template <class LaneOp, class ScalarOp>
void expect_lanewise(const std::vector<float>& values, LaneOp op, ScalarOp scalar, const char* what) {
    for (size_t i = 0; i + kLanes <= values.size(); i += kLanes) {
        const Float x = Float::load(&values[i]);
        const auto r = op(x);
        for (int lane = 0; lane < kLanes; ++lane) {
            const auto want = scalar(values[i + size_t(lane)]);
            if constexpr (std::is_same_v<std::remove_cv_t<decltype(want)>, float>)
                ASSERT_EQ(bits_of(r[lane]), bits_of(want)) << what << "(" << values[i + size_t(lane)] << ")";
            else
                ASSERT_EQ(r[lane], want) << what << "(" << values[i + size_t(lane)] << ")";
        }
    }
}

// What x86's cvttps2dq and cvtps2dq give: the value, or INT32_MIN outside
// the int32 range and for NaN.
int32_t x86_trunc(float x) { return x >= -2147483648.0f && x < 2147483648.0f ? int32_t(x) : INT32_MIN; }
int32_t x86_round(float x) {
    return x >= -2147483648.0f && x < 2147483648.0f ? int32_t(std::nearbyint(x)) : INT32_MIN;
}

}  // namespace

TEST(Lanes, ArithmeticIsTheScalarsLaneByLane) {
    const std::vector<float> v = awkward_floats();
    std::vector<float> w(v.rbegin(), v.rend());
    std::vector<float> u(v);
    std::rotate(u.begin(), u.begin() + 5, u.end());
    for (size_t i = 0; i + kLanes <= v.size(); i += kLanes) {
        const Float a = Float::load(&v[i]), b = Float::load(&w[i]), c = Float::load(&u[i]);
        const Float sum = a + b, product = a * b, quotient = a / b, fused = fmuladd(a, b, c);
        const Float larger = fmax(a, b), smaller = fmin(a, b);
        for (int lane = 0; lane < kLanes; ++lane) {
            const float x = v[i + size_t(lane)], y = w[i + size_t(lane)], z = u[i + size_t(lane)];
            ASSERT_EQ(bits_of(sum[lane]), bits_of(x + y));
            ASSERT_EQ(bits_of(product[lane]), bits_of(x * y));
            ASSERT_EQ(bits_of(quotient[lane]), bits_of(x / y));
            ASSERT_EQ(bits_of(fused[lane]), bits_of(std::fma(x, y, z))) << x << " " << y << " " << z;
            // A NaN operand gives the other one (signalling NaNs too, where
            // std::fmax may return NaN); otherwise the larger (smaller).
            const float want_max = std::isnan(x) ? y : std::isnan(y) ? x : (x < y ? y : x);
            const float want_min = std::isnan(x) ? y : std::isnan(y) ? x : (y < x ? y : x);
            ASSERT_EQ(bits_of(larger[lane]), bits_of(want_max)) << x << " " << y;
            ASSERT_EQ(bits_of(smaller[lane]), bits_of(want_min)) << x << " " << y;
        }
    }
}

TEST(Lanes, RoundingAndConversionsAreDefinedForEveryInput) {
    // In the shading threads' environment (raster/float_env.h): flush to
    // zero and denormals are zero, so roundps rounds a denormal as +-0 and
    // the portable forms must too (floor(-denormal) is -0.0, not -1).
    const unsigned saved_csr = _mm_getcsr();
    _mm_setcsr(saved_csr | 0x8040u);
    const std::vector<float> v = awkward_floats();
    expect_lanewise(v, [](Float x) { return sqrt(x); }, [](float x) { return std::sqrt(x); }, "sqrt");
    // roundps quiets a signalling NaN, as the x86 arithmetic does.
    const auto daz = [](float x) {
        const uint32_t b = std::bit_cast<uint32_t>(x);
        return std::isnan(x) ? std::bit_cast<float>(b | 0x00400000u) : denormal_as_zero(x);
    };
    expect_lanewise(v, [](Float x) { return floor(x); }, [&](float x) { return std::floor(daz(x)); }, "floor");
    expect_lanewise(v, [](Float x) { return ceil(x); }, [&](float x) { return std::ceil(daz(x)); }, "ceil");
    expect_lanewise(v, [](Float x) { return trunc(x); }, [&](float x) { return std::trunc(daz(x)); }, "trunc");
    // In float, so beyond 2^31 a value comes back as it is (the mirror wrap
    // of a huge texture coordinate relies on it).
    expect_lanewise(v, [](Float x) { return round_even(x); }, [&](float x) { return std::nearbyint(daz(x)); },
                    "round_even");
    expect_lanewise(v, [](Float x) { return abs(x); }, [](float x) { return std::fabs(x); }, "abs");
    expect_lanewise(v, [](Float x) { return itrunc(x); }, x86_trunc, "itrunc");
    expect_lanewise(v, [](Float x) { return iround(x); }, x86_round, "iround");
    _mm_setcsr(saved_csr);
}

TEST(Lanes, MasksAndBits) {
    for (unsigned b : {0u, 1u, 0x5u, (1u << kLanes) - 1, 1u << (kLanes - 1), 0xa5a5u & ((1u << kLanes) - 1)}) {
        const Mask m = Mask::from_bits(b);
        EXPECT_EQ(bits(m), b);
        EXPECT_EQ(any(m), b != 0);
        EXPECT_EQ(all(m), b == (1u << kLanes) - 1);
        EXPECT_EQ(none(m), b == 0);
        for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(m[lane], bool(b >> lane & 1));
    }
    EXPECT_EQ(bits(Float(std::numeric_limits<float>::quiet_NaN()) < Float(1.0f)), 0u);
}

TEST(Lanes, OddBytesAndAnyBit) {
    Int x;
    for (int lane = 0; lane < kLanes; ++lane) x.set(lane, int32_t(0x9e3779b9u * unsigned(lane + 1)));
    const Int odd = odd_bytes(x);
    for (int lane = 0; lane < kLanes; ++lane)
        EXPECT_EQ(uint32_t(odd[lane]), (uint32_t(x[lane]) >> 8) & 0x00ff00ffu) << lane;
    EXPECT_FALSE(any_bit(Int(0)));
    for (int lane = 0; lane < kLanes; ++lane) {
        Int one(0);
        one.set(lane, int32_t(0x80000000u));
        EXPECT_TRUE(any_bit(one)) << lane;
        one.set(lane, 1);
        EXPECT_TRUE(any_bit(one)) << lane;
    }
}

TEST(Lanes, PermuteReduceAndMulhrs) {
    Int table, idx;
    for (int lane = 0; lane < kLanes; ++lane) {
        table.set(lane, 100 + lane * 7 - (lane == 3 ? 500 : 0));
        idx.set(lane, (lane * 5 + 3) % kLanes);
    }
    const Int p = permute(table, idx);
    int32_t lo = table[0], hi = table[0];
    for (int lane = 0; lane < kLanes; ++lane) {
        EXPECT_EQ(p[lane], table[idx[lane]]);
        lo = std::min(lo, table[lane]);
        hi = std::max(hi, table[lane]);
    }
    EXPECT_EQ(reduce_min(table), lo);
    EXPECT_EQ(reduce_max(table), hi);
    // permute2: indices into table followed by a second table, both halves
    // reached (every lane of idx2 differs, and lanes take either half).
    Int second, idx2;
    for (int lane = 0; lane < kLanes; ++lane) {
        second.set(lane, -1000 - lane * 13);
        idx2.set(lane, (lane * 7 + 5) % (2 * kLanes));
    }
    const Int p2 = permute2(table, second, idx2);
    for (int lane = 0; lane < kLanes; ++lane)
        EXPECT_EQ(p2[lane], idx2[lane] < kLanes ? table[idx2[lane]] : second[idx2[lane] - kLanes]) << lane;
    // The reductions see every lane: a minimum or maximum in any one.
    for (int at = 0; at < kLanes; ++at) {
        Int one(5);
        one.set(at, -7);
        EXPECT_EQ(reduce_min(one), -7) << at;
        one.set(at, 9);
        EXPECT_EQ(reduce_max(one), 9) << at;
    }
    // pmulhrsw per 16-bit half, against its definition.
    std::mt19937 rng(3);
    for (int round = 0; round < 1000; ++round) {
        Int a, b;
        for (int lane = 0; lane < kLanes; ++lane) {
            a.set(lane, int32_t(rng()));
            b.set(lane, int32_t(rng()));
        }
        const Int r = mulhrs16(a, b);
        for (int lane = 0; lane < kLanes; ++lane)
            for (int half = 0; half < 2; ++half) {
                const auto x = int16_t(uint32_t(a[lane]) >> (16 * half)), y = int16_t(uint32_t(b[lane]) >> (16 * half));
                const auto want = int16_t((int32_t(x) * int32_t(y) + 0x4000) >> 15);
                ASSERT_EQ(int16_t(uint32_t(r[lane]) >> (16 * half)), want);
            }
    }
}

// Inactive lanes read nothing: their indices point far outside the array.
TEST(Lanes, GathersReadOnlyActiveLanes) {
    std::vector<int32_t> ints(64);
    std::vector<float> floats(64);
    for (int i = 0; i < 64; ++i) {
        ints[size_t(i)] = i * 3;
        floats[size_t(i)] = float(i) * 0.5f;
    }
    Int index;
    unsigned active = 0;
    for (int lane = 0; lane < kLanes; ++lane) {
        const bool on = lane % 3 != 1;
        index.set(lane, on ? (lane * 11) % 64 : 1 << 30);
        active |= unsigned(on) << lane;
    }
    const Int gi = gather(ints.data(), index, Mask::from_bits(active));
    const Float gf = gather(floats.data(), index, Mask::from_bits(active));
    Int first, second;
    Int pair_index;
    for (int lane = 0; lane < kLanes; ++lane) pair_index.set(lane, (lane * 11) % 63);
    gather_pairs(ints.data(), pair_index, first, second);
    for (int lane = 0; lane < kLanes; ++lane) {
        const bool on = active >> lane & 1;
        EXPECT_EQ(gi[lane], on ? ints[size_t(index[lane])] : 0);
        EXPECT_EQ(gf[lane], on ? floats[size_t(index[lane])] : 0.0f);
        EXPECT_EQ(first[lane], ints[size_t(pair_index[lane])]);
        EXPECT_EQ(second[lane], ints[size_t(pair_index[lane]) + 1]);
    }
}

// load_rows8 against the plain definition: every lane its own offset
// (unaligned, repeated, the array's last eight floats), every float in place.
TEST(Lanes, LoadRows8Transposes) {
    std::vector<float> data(1000);
    for (size_t i = 0; i < data.size(); ++i) data[i] = float(i) * 0.5f - 7.0f;
    Int offset;
    for (int i = 0; i < kLanes; ++i) offset.set(i, i == 3 ? 992 : (i * 37 + 5) % 900);
    Float out[8];
    load_rows8(data.data(), offset, out);
    for (int i = 0; i < kLanes; ++i)
        for (int c = 0; c < 8; ++c) EXPECT_EQ(out[c][i], data[size_t(offset[i] + c)]) << "lane " << i << " float " << c;
}

}  // namespace st::simd

namespace st::simd {
// UInt is GLSL's uint: unsigned compares, logical shifts with the count
// masked to 5 bits as gallivm masks it, float(u) correctly rounded.
TEST(Lanes, UIntIsUnsigned) {
    std::mt19937 rng(3);
    for (int round = 0; round < 200; ++round) {
        UInt a, b;
        Int n;
        for (int lane = 0; lane < kLanes; ++lane) {
            a.set(lane, lane == 0 ? 0xFFFFFFFFu : lane == 1 ? 0x80000001u : uint32_t(rng()));
            b.set(lane, uint32_t(rng()));
            n.set(lane, int32_t(rng() % 70) - 3);
        }
        const Float f = to_float(a);
        const Mask lt = a < b;
        const UInt sr = a >> UInt(n), sl = a << UInt(n);
        const Int ar = ashr(Int(a.v), n);
        Float in_range;  // [0, 2^32): where uint(f) is defined
        for (int lane = 0; lane < kLanes; ++lane) in_range.set(lane, float(a[lane]) * float(lane) / float(kLanes));
        const UInt u = to_uint(in_range);
        for (int lane = 0; lane < kLanes; ++lane) {
            ASSERT_EQ(f[lane], float(a[lane]));
            ASSERT_EQ(lt[lane], a[lane] < b[lane]);
            ASSERT_EQ(sr[lane], a[lane] >> (uint32_t(n[lane]) & 31u));
            ASSERT_EQ(sl[lane], a[lane] << (uint32_t(n[lane]) & 31u));
            ASSERT_EQ(ar[lane], int32_t(a[lane]) >> (uint32_t(n[lane]) & 31u));
            ASSERT_EQ(u[lane], uint32_t(in_range[lane])) << in_range[lane];
        }
    }
}
}  // namespace st::simd
