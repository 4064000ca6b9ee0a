// SPDX-License-Identifier: GPL-2.0-or-later
// kins_test_util.hpp - poses and joint arrays for the kinematics unit tests.
#pragma once
#include <array>
#include <cmath>
#include <gtest/gtest.h>

#include "kins_models.h"

using Joints = std::array<double, KINS_MAX_JOINTS>;

inline EmcPose pose(double x, double y, double z, double a = 0, double b = 0, double c = 0,
                    double u = 0, double v = 0, double w = 0)
{
    EmcPose p{};
    p.tran = {x, y, z};
    p.a = a;
    p.b = b;
    p.c = c;
    p.u = u;
    p.v = v;
    p.w = w;
    return p;
}

inline Joints joints(std::initializer_list<double> v)
{
    Joints j{};
    std::size_t i = 0;
    for (double x : v)
        j[i++] = x;
    return j;
}

// The angle difference folded into (-180, 180]: A = 180 and A = -180 are one orientation.
inline double angle_diff(double a, double b)
{
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0)
        d -= 360.0;
    if (d <= -180.0)
        d += 360.0;
    return d;
}

inline void expect_pose_near(const EmcPose& got, const EmcPose& want, double tol)
{
    EXPECT_NEAR(got.tran.x, want.tran.x, tol);
    EXPECT_NEAR(got.tran.y, want.tran.y, tol);
    EXPECT_NEAR(got.tran.z, want.tran.z, tol);
    EXPECT_NEAR(angle_diff(got.a, want.a), 0.0, tol) << "A " << got.a << " vs " << want.a;
    EXPECT_NEAR(angle_diff(got.b, want.b), 0.0, tol) << "B " << got.b << " vs " << want.b;
    EXPECT_NEAR(angle_diff(got.c, want.c), 0.0, tol) << "C " << got.c << " vs " << want.c;
    EXPECT_NEAR(got.u, want.u, tol);
    EXPECT_NEAR(got.v, want.v, tol);
    EXPECT_NEAR(got.w, want.w, tol);
}

inline void expect_joints_near(const Joints& got, std::initializer_list<double> want, double tol,
                               bool angles = false)
{
    std::size_t i = 0;
    for (double w : want) {
        if (angles)
            EXPECT_NEAR(angle_diff(got[i], w), 0.0, tol) << "joint " << i;
        else
            EXPECT_NEAR(got[i], w, tol) << "joint " << i;
        ++i;
    }
}

// A small deterministic generator (the tests must not depend on the library's).
struct Lcg {
    unsigned long long s;
    double uniform(double lo, double hi)
    {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return lo + (hi - lo) * double(s >> 11) / double(1ULL << 53);
    }
};
