// SPDX-License-Identifier: GPL-2.0-or-later
// main.cpp - rtapi_app, the simulated-realtime module host. halcmd starts it on
// demand (rtapi_client.hpp) and talks to it over its socket; it takes no arguments.
#include <cstdio>
#include <exception>

#include "daemon.hpp"

int main(int argc, char** argv)
{
    if (argc > 1) {
        std::fprintf(stderr, "usage: %s\n(started by halcmd loadrt; serves "
                             "/tmp/rtapi-<uid>-$RTAPI_INSTANCE.sock)\n", argv[0]);
        return 1;
    }
    try {
        return hal::run_daemon();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rtapi_app: %s\n", e.what());
        return 1;
    }
}
