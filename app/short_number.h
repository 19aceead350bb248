// short_number.h: a number as the sweeps' and reports' tables print it, to a
// few significant digits in its shortest form.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>

namespace st {

inline std::string short_number(double v, int precision = 3) {
    std::ostringstream s;
    s << std::setprecision(precision) << v;
    return s.str();
}

}  // namespace st
