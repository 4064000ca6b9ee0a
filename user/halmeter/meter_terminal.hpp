// SPDX-License-Identifier: GPL-2.0-or-later
// meter_terminal.hpp - halmeter without a display: the value updated in place on a
// terminal ("NAME = VALUE", redrawn each interval), or one "VALUE" line per interval
// for scripts (-l, or stdout not a terminal).
#pragma once

#include <cstdio>
#include <string>

#include "meter_options.hpp"

namespace hal::meter {

// The text of one update: in place "\rNAME = VALUE\033[K" (erase what a longer value
// left), else "VALUE\n". Pure, for the unit tests.
std::string terminal_update(const Item& item, const std::string& value, bool in_place);

// Runs until COUNT updates, SIGINT/SIGTERM, or the item disappears (exit status 1).
int run_terminal(const MeterOptions& o);

}  // namespace hal::meter
