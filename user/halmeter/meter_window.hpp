// SPDX-License-Identifier: GPL-2.0-or-later
// meter_window.hpp - halmeter's GTK 3 window as halmeter(1) describes it: the value
// (large), the item's name, "Select" and "Exit" buttons; -s puts the name in the
// title bar and drops the buttons; -g places and sizes the window.
//
// Test hook: with HALMETER_REPORT=FILE set, every change of what the window shows is
// appended to FILE as "title=T|name=N|value=V" (the texts of the GTK labels), so a
// test under Xvfb can check what is displayed; HALMETER_TEST_SELECT="sig NAME" (or pin/
// param) drives the Select dialog once the window is up: it picks NAME in its tab and
// presses Apply, then OK, as a user would.
#pragma once

#include "meter_options.hpp"

namespace hal::meter {

// Returns the exit status; 1 with a message when no display can be opened.
int run_window(const MeterOptions& o, int& argc, char**& argv);

}  // namespace hal::meter
