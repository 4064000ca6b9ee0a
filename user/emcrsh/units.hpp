// SPDX-License-Identifier: GPL-2.0-or-later
// units.hpp - emcrsh's unit names and display conversions: machine units named by
// closeness (emcrsh(1): 0.03937 per mm is INCH, 1 MM, 0.1 CM, else CUSTOM) and
// offsets converted for LINEAR_/ANGULAR_UNIT_CONVERSION.
#pragma once

#include <string>

namespace hal::emcrsh {

// units_per_mm: machine units per millimetre (status traj.units_per_mm).
std::string linear_units_name(double units_per_mm);
// The INI's [TRAJ]ANGULAR_UNITS (status traj.angular_units): a name (degree, deg,
// radian, rad, grad, gon) or units per degree; "" is degrees.
std::string angular_units_name(const std::string& ini_value);
// A machine-unit length in the conversion's units (INCH MM CM; AUTO: the program's
// units MM/INCH; CUSTOM: unchanged).
double convert_linear(double v, double units_per_mm, const std::string& conv, const std::string& program_units);
// A machine-unit angle in the conversion's units (DEG RAD GRAD; AUTO: DEG; CUSTOM).
double convert_angular(double v, const std::string& ini_value, const std::string& conv);

}  // namespace hal::emcrsh
