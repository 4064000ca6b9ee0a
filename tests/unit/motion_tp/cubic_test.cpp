// The cubic interpolator between trajectory points.
#include <cmath>
#include <gtest/gtest.h>
extern "C" {
#include "cubic.h"
}

TEST(Cubic, RateOneIsASmoothedDelay)
{
	cubic cb{};
	ASSERT_EQ(cubic_init(&cb, 0.001, 0.001), 0);
	EXPECT_EQ(cb.rate, 1);
	// constant velocity 10 units/s: output is exact, two points behind
	double out = 0;
	for (int k = 0; k < 20; k++) {
		ASSERT_TRUE(cubic_needs_next_point(&cb));
		cubic_add_point(&cb, 0.01 * k);
		out = cubic_interpolate(&cb, nullptr, nullptr);
	}
	EXPECT_NEAR(out, 0.01 * 18, 1e-12);
}

TEST(Cubic, InterpolatesBetweenPointsWithRate)
{
	cubic cb{};
	ASSERT_EQ(cubic_init(&cb, 0.004, 0.001), 0);
	EXPECT_EQ(cb.rate, 4);
	double prev = 0, vel = 0;
	int adds = 0;
	for (int k = 0; k < 400; k++) {
		if (cubic_needs_next_point(&cb)) {
			cubic_add_point(&cb, 5.0 * (adds * 0.004));	// 5 units/s ramp
			adds++;
		}
		double p = cubic_interpolate(&cb, &vel, nullptr);
		if (k > 20) {
			EXPECT_NEAR(p - prev, 0.005, 1e-12);
			EXPECT_NEAR(vel, 5.0, 1e-9);
		}
		prev = p;
	}
	EXPECT_EQ(adds, 100);
}

TEST(Cubic, DrainAndOffset)
{
	cubic cb{};
	ASSERT_EQ(cubic_init(&cb, 0.001, 0.001), 0);
	cubic_add_point(&cb, 3.0);
	EXPECT_DOUBLE_EQ(cubic_interpolate(&cb, nullptr, nullptr), 3.0);
	cubic_offset(&cb, 1.0);
	cubic_add_point(&cb, 4.0);
	EXPECT_NEAR(cubic_interpolate(&cb, nullptr, nullptr), 4.0, 1e-12);
	cubic_drain(&cb);
	EXPECT_TRUE(cubic_needs_next_point(&cb));
	cubic_add_point(&cb, -2.0);
	EXPECT_DOUBLE_EQ(cubic_interpolate(&cb, nullptr, nullptr), -2.0);
	EXPECT_EQ(cubic_init(&cb, 0.001, 0), -1);
	EXPECT_EQ(cubic_init(&cb, 0.0005, 0.001), -1);
}
