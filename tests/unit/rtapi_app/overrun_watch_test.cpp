// SPDX-License-Identifier: GPL-2.0-or-later
// overrun_watch_test - the realtime host's warning about missed periods (issue 19,
// item 3): one line per thread whose count grew since the last look, none otherwise.
#include "overrun_watch.hpp"

#include <gtest/gtest.h>

namespace {

TEST(OverrunWatch, WarnsOnceWhenTheCountGrows)
{
    hal::OverrunWatch w;
    EXPECT_EQ(w.update("fast", 1000, 0), "");
    EXPECT_EQ(w.update("fast", 1000, 88403),
              "rtapi_app: thread 'fast' (period 1000 ns) missed 88403 periods in the last "
              "1000 ms (88403 since it started; pin fast.overruns): it cannot keep up, use a "
              "longer period or fewer functions");
    EXPECT_EQ(w.update("fast", 1000, 88403), "");  // no new misses: silent
    EXPECT_EQ(w.update("fast", 1000, 88404),
              "rtapi_app: thread 'fast' (period 1000 ns) missed 1 period in the last 1000 ms "
              "(88404 since it started; pin fast.overruns): it cannot keep up, use a longer "
              "period or fewer functions");
}

TEST(OverrunWatch, ThreadsAreCountedApart)
{
    hal::OverrunWatch w;
    EXPECT_NE(w.update("a", 1000, 5), "");
    EXPECT_EQ(w.update("b", 2000, 0), "");
    EXPECT_EQ(w.update("a", 1000, 5), "");
    EXPECT_NE(w.update("b", 2000, 1), "");
}

TEST(OverrunWatch, ARecreatedThreadStartsAgain)
{
    hal::OverrunWatch w;
    EXPECT_NE(w.update("t", 1000, 50), "");
    EXPECT_EQ(w.update("t", 1000, 3), "");   // deleted and made again: fewer than before
    EXPECT_NE(w.update("t", 1000, 4), "");
}

}  // namespace
