// SPDX-License-Identifier: GPL-2.0-or-later
// units.cpp - unit names and conversions (units.hpp).
#include "units.hpp"

#include <cmath>
#include <algorithm>
#include <cstdlib>

#include "text.hpp"

namespace hal::emcrsh {

static bool near(double a, double b) { return std::fabs(a - b) < 1e-4 * std::max(1.0, std::fabs(b)); }

std::string linear_units_name(double per_mm)
{
    if (near(per_mm, 1.0))
        return "MM";
    if (near(per_mm, 1.0 / 25.4))
        return "INCH";
    if (near(per_mm, 0.1))
        return "CM";
    return "CUSTOM";
}

// machine angle units per degree; 0 when the value names nothing known
static double per_degree(const std::string& ini_value)
{
    std::string u = upper(ini_value);
    if (u.empty() || u == "DEG" || u == "DEGREE" || u == "DEGREES")
        return 1.0;
    if (u == "RAD" || u == "RADIAN" || u == "RADIANS")
        return M_PI / 180.0;
    if (u == "GRAD" || u == "GON")
        return 400.0 / 360.0;
    char* end = nullptr;
    double v = std::strtod(ini_value.c_str(), &end);
    return (*end == '\0' && v > 0) ? v : 0.0;
}

std::string angular_units_name(const std::string& ini_value)
{
    double p = per_degree(ini_value);
    if (near(p, 1.0))
        return "DEG";
    if (near(p, M_PI / 180.0))
        return "RAD";
    if (near(p, 400.0 / 360.0))
        return "GRAD";
    return "CUSTOM";
}

double convert_linear(double v, double units_per_mm, const std::string& conv, const std::string& program_units)
{
    std::string c = conv == "AUTO" ? (program_units == "INCH" ? "INCH" : "MM") : conv;
    if (c == "CUSTOM" || units_per_mm <= 0)
        return v;
    double mm = v / units_per_mm;
    return c == "INCH" ? mm / 25.4 : c == "CM" ? mm / 10.0 : mm;
}

double convert_angular(double v, const std::string& ini_value, const std::string& conv)
{
    double p = per_degree(ini_value);
    std::string c = conv == "AUTO" ? "DEG" : conv;
    if (c == "CUSTOM" || p <= 0)
        return v;
    double deg = v / p;
    return c == "RAD" ? deg * M_PI / 180.0 : c == "GRAD" ? deg * 400.0 / 360.0 : deg;
}

}  // namespace hal::emcrsh
