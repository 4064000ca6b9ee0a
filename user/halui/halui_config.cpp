// SPDX-License-Identifier: GPL-2.0-or-later
// halui_config.cpp - the INI keys halui reads (halui_config.hpp). Defaults and the
// coordinate/joint rules are those task applies (user/task/task_config.cpp), so both
// agree on the machine's shape.
#include "halui_config.hpp"

#include <cctype>
#include <cstring>

#include "ini/ini_reader.hpp"

namespace hal::halui {

Result<Config> read_config(const ini::IniFile& ini)
{
    Config c;
    ini::Reader r{ini, {}};
    std::string coords = "XYZ";
    r.coordinates(coords);
    bool seen[9] = {};
    for (char ch : coords)
        seen[ini::axis_index(ch)] = true;   // coordinates() let only axis letters through
    c.joints = static_cast<int>(coords.size());   // the default: one joint per letter (a gantry repeats one)
    for (int a = 0; a < 9; ++a)
        if (seen[a])
            c.axes.push_back(a);
    r.i("KINS", "JOINTS", c.joints);
    r.i("TRAJ", "SPINDLES", c.spindles);
    r.range("KINS", "JOINTS", c.joints, 1, MAX_JOINTS);
    r.range("TRAJ", "SPINDLES", c.spindles, 0, MAX_SPINDLES);
    r.d("DISPLAY", "MAX_FEED_OVERRIDE", c.max_feed_override);
    r.d("DISPLAY", "MIN_SPINDLE_OVERRIDE", c.min_spindle_override);
    r.d("DISPLAY", "MAX_SPINDLE_OVERRIDE", c.max_spindle_override);
    if (ini.find("TRAJ", "MAX_LINEAR_VELOCITY"))
        r.d("TRAJ", "MAX_LINEAR_VELOCITY", c.max_velocity);
    else
        r.d("AXIS_X", "MAX_VELOCITY", c.max_velocity);
    r.range("DISPLAY", "MAX_FEED_OVERRIDE", c.max_feed_override, 0, 1e6);
    r.range("DISPLAY", "MIN_SPINDLE_OVERRIDE", c.min_spindle_override, 0, 1e6);
    r.range("DISPLAY", "MAX_SPINDLE_OVERRIDE", c.max_spindle_override, 0, 1e6);
    if (!r.err.empty())
        return Error{-1, r.err};
    if (c.max_spindle_override < c.min_spindle_override)
        return Error{-1, ini.where("DISPLAY", "MAX_SPINDLE_OVERRIDE") + ": [DISPLAY]MAX_SPINDLE_OVERRIDE: " +
                             ini::Reader::num(c.max_spindle_override) + " is below MIN_SPINDLE_OVERRIDE " +
                             ini::Reader::num(c.min_spindle_override)};
    if (c.max_velocity < 0)
        return Error{-1, ini.where("TRAJ", "MAX_LINEAR_VELOCITY") + ": the maximum velocity must not be negative"};

    c.mdi = ini.find_all("HALUI", "MDI_COMMAND");
    if (c.mdi.size() > MAX_MDI_COMMANDS)
        return Error{-1, ini.where("HALUI", "MDI_COMMAND", MAX_MDI_COMMANDS + 1) +
                             ": [HALUI]MDI_COMMAND: more than " + std::to_string(MAX_MDI_COMMANDS) + " commands"};
    for (size_t k = 0; k < c.mdi.size(); ++k) {
        bool blank = c.mdi[k].find_first_not_of(" \t") == std::string::npos;
        bool control = false;
        for (unsigned char ch : c.mdi[k])
            control |= ch < 0x20 && ch != '\t';
        if (blank || control)
            return Error{-1, ini.where("HALUI", "MDI_COMMAND", static_cast<int>(k) + 1) + ": [HALUI]MDI_COMMAND: " +
                                 (blank ? "empty command" : "control characters in the command")};
    }
    return c;
}

}  // namespace hal::halui
