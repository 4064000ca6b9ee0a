// SPDX-License-Identifier: GPL-2.0-or-later
// meter_window_none.cpp - run_window() of a halmeter built without GTK (the static
// tools of the kernel-test VM, which has no display): only terminal mode is there.
#include <cstdio>

#include "meter_window.hpp"

namespace hal::meter {

int run_window(const MeterOptions&, int&, char**&)
{
    std::fprintf(stderr, "halmeter: this build has no GTK window; use -t for terminal mode\n");
    return 1;
}

}  // namespace hal::meter
