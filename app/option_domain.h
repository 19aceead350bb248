// option_domain.h: a numeric option's domain as a CLI11 check (issue 26,
// point 4). app/cli.cpp declares each numeric option's domain once, where
// the option is defined; the parser then refuses any value outside it (out
// of range, no number of the option's kind, empty, NaN, infinite, a
// denormal below the least value) with one line that names the option and
// the domain, "shadertwin: --grid: '1.5' is outside its domain, a power of
// two in [8, 2048]", and exit 2, before anything is computed or written.
#pragma once

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

namespace st {

// The whole string as a real number (strtod's syntax, "inf" and "nan"
// included), or nothing.
inline std::optional<double> option_real(const std::string& v) {
    if (v.empty() || std::isspace(static_cast<unsigned char>(v[0]))) return std::nullopt;
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (end != v.c_str() + v.size()) return std::nullopt;
    return x;
}

// The whole string as a decimal integer that a long long holds, or nothing
// ("1.5", "1e6" and 9223372036854775808 are not).
inline std::optional<long long> option_integer(const std::string& v) {
    if (v.empty() || !(std::isdigit(static_cast<unsigned char>(v[0])) || v[0] == '-' || v[0] == '+'))
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const long long x = std::strtoll(v.c_str(), &end, 10);
    if (errno != 0 || end != v.c_str() + v.size()) return std::nullopt;
    return x;
}

// A bound as the domains print it: 1e9, 1e-12, 0.01, 10000000.
inline std::string domain_number(double v) {
    std::ostringstream s;
    if (v == std::floor(v) && std::abs(v) < 1e8) {
        s << static_cast<long long>(v);
        return s.str();
    }
    s << v;
    std::string t = s.str();  // 1e+09, 1e-12
    const size_t e = t.find('e');
    if (e == std::string::npos) return t;
    std::string mantissa = t.substr(0, e), exponent = t.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent = exponent.substr(exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
    exponent.erase(0, exponent.find_first_not_of('0'));
    return mantissa + "e" + (negative ? "-" : "") + exponent;
}

// The values an option takes: `text` says them (in --help and in a
// refusal), `accepts` decides.
struct OptionDomain {
    std::string text;
    std::function<bool(const std::string&)> accepts;

    CLI::Validator check() const {
        const std::string t = text;
        const auto a = accepts;
        return CLI::Validator(
            [t, a](std::string& value) {
                if (value.empty()) return "an empty value is not a number; its domain is " + t;
                return a(value) ? std::string() : "'" + value + "' is outside its domain, " + t;
            },
            t, "DOMAIN");
    }
};

// Reals in [lo, hi] (`unit` after the interval: "per mm", "mm").
inline OptionDomain reals_in(double lo, double hi, const std::string& unit = "") {
    return {"[" + domain_number(lo) + ", " + domain_number(hi) + "]" + (unit.empty() ? "" : " " + unit),
            [lo, hi](const std::string& v) {
                const auto x = option_real(v);
                return x && *x >= lo && *x <= hi;
            }};
}

// Integers in [lo, hi].
inline OptionDomain integers_in(long long lo, long long hi) {
    return {"an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", [lo, hi](const std::string& v) {
                const auto x = option_integer(v);
                return x && *x >= lo && *x <= hi;
            }};
}

}  // namespace st
