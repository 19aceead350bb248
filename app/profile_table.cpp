// profile_table.cpp: see profile_table.h.
#include "app/profile_table.h"

#include <cmath>
#include <iomanip>
#include <stdexcept>
#include <sstream>

#include "scene/input_error.h"

namespace st {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string csv_text(const ProfileTable& t) {
    std::ostringstream csv;
    csv << std::setprecision(9);
    if (t.R.size() == 1) csv << "r_mm,R,T\n";
    else csv << "r_mm,R_r,R_g,R_b,T_r,T_g,T_b\n";
    for (size_t i = 0; i < t.radii.size(); ++i) {
        csv << t.radii[i];
        for (const auto& c : t.R) csv << ',' << c[i];
        for (const auto& c : t.T) csv << ',' << c[i];
        csv << '\n';
    }
    return csv.str();
}

Image exr_rows(const ProfileTable& t) {
    Image rows(int(t.radii.size()), 2);
    for (size_t i = 0; i < t.radii.size(); ++i) {
        float* r = rows.pixel(int(i), 0);
        float* tr = rows.pixel(int(i), 1);
        for (size_t c = 0; c < 3; ++c) {
            const size_t k = t.R.size() == 1 ? 0 : c;
            r[c] = float(t.R[k][i]);
            tr[c] = float(t.T[k][i]);
        }
        r[3] = tr[3] = float(t.radii[i]);
    }
    return rows;
}

}  // namespace

void check_profile_path(const std::string& path) {
    if (!ends_with(path, ".csv") && !ends_with(path, ".exr"))
        throw InputError("profile --out must name a .csv or .exr file: " + path);
}

void write_profile_table(const std::string& path, const ProfileTable& table) {
    check_profile_path(path);
    for (const auto* channels : {&table.R, &table.T})
        for (const auto& c : *channels)
            for (double v : c)
                if (!std::isfinite(v))
                    throw std::runtime_error("a profile value is not finite for these inputs (a defect: please "
                                             "report the command); " + path + " not written");
    if (ends_with(path, ".exr")) {
        Metadata m = table.metadata;
        m["layout"] = "row 0: R(r) rgb, row 1: T(r) rgb, per mm^2; alpha: r in mm";
        write_exr(path, exr_rows(table), m);
    } else {
        write_text_file(path, csv_text(table));
    }
}

}  // namespace st
