// SPDX-License-Identifier: GPL-2.0-or-later
// The shared geometry of the kinematics modules (kernel/kins/kins_math_fp.c).
#include "kins_test_util.hpp"

namespace {

TEST(KinsMath, RollPitchYawRoundTrip)
{
    Lcg rng{11};
    for (int n = 0; n < 500; ++n) {
        double a = rng.uniform(-3.1, 3.1), b = rng.uniform(-1.5, 1.5), c = rng.uniform(-3.1, 3.1);
        double r[3][3], a2, b2, c2;
        kins_rpy_to_rot(a, b, c, r);
        kins_rot_to_rpy(r, &a2, &b2, &c2);
        EXPECT_NEAR(a2, a, 1e-12);
        EXPECT_NEAR(b2, b, 1e-12);
        EXPECT_NEAR(c2, c, 1e-12);
    }
}

TEST(KinsMath, RollPitchYawIsRzRyRx)
{
    double r[3][3];
    kins_rpy_to_rot(0, 0, KINS_PI / 2, r);  // yaw 90°: X -> Y
    kins_vec v = kins_rot_apply(r, {1, 0, 0});
    EXPECT_NEAR(v.x, 0, 1e-15);
    EXPECT_NEAR(v.y, 1, 1e-15);
    kins_rpy_to_rot(KINS_PI / 2, 0, 0, r);  // roll 90°: Y -> Z
    v = kins_rot_apply(r, {0, 1, 0});
    EXPECT_NEAR(v.z, 1, 1e-15);
    kins_rpy_to_rot(KINS_PI / 2, 0, KINS_PI / 2, r);  // roll first, then yaw: Y -> Z -> Z
    v = kins_rot_apply(r, {0, 1, 0});
    EXPECT_NEAR(v.z, 1, 1e-15);
}

TEST(KinsMath, GimbalLockKeepsTheRotation)
{
    double r[3][3], back[3][3], a, b, c;
    kins_rpy_to_rot(0.3, KINS_PI / 2, 0.7, r);
    kins_rot_to_rpy(r, &a, &b, &c);
    EXPECT_NEAR(b, KINS_PI / 2, 1e-7);
    kins_rpy_to_rot(a, b, c, back);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(back[i][k], r[i][k], 1e-7);
}

TEST(KinsMath, RotationVectorOfKnownRotations)
{
    double r[3][3];
    kins_rpy_to_rot(0, 0, 0.25, r);
    kins_vec v = kins_rot_to_vector(r);
    EXPECT_NEAR(v.z, 0.25, 1e-15);
    EXPECT_NEAR(v.x, 0, 1e-15);
    kins_rpy_to_rot(KINS_PI, 0, 0, r);  // a half turn about X
    v = kins_rot_to_vector(r);
    EXPECT_NEAR(std::fabs(v.x), KINS_PI, 1e-12);
    EXPECT_NEAR(v.y, 0, 1e-12);
    kins_rpy_to_rot(0, 0, 0, r);
    v = kins_rot_to_vector(r);
    EXPECT_EQ(v.x, 0);
    EXPECT_EQ(v.y, 0);
    EXPECT_EQ(v.z, 0);
}

TEST(KinsMath, SolveFindsTheSolutionAndRefusesSingularSystems)
{
    double a[9] = {0, 2, 1, 1, 1, 1, 2, 1, 0};  // needs a row swap
    double b[3] = {5, 4, 4};                     // x = (1, 2, 1)
    ASSERT_EQ(kins_solve(3, a, b), 0);
    EXPECT_NEAR(b[0], 1, 1e-12);
    EXPECT_NEAR(b[1], 2, 1e-12);
    EXPECT_NEAR(b[2], 1, 1e-12);
    double s[4] = {1, 2, 2, 4}, t[2] = {1, 2};
    EXPECT_EQ(kins_solve(2, s, t), -1);
    double z[1] = {0}, u[1] = {1};
    EXPECT_EQ(kins_solve(1, z, u), -1);
    EXPECT_EQ(kins_solve(KINS_SOLVE_MAX + 1, s, t), -1);
}

TEST(KinsMath, PoseAxesByIndex)
{
    EmcPose p = pose(1, 2, 3, 4, 5, 6, 7, 8, 9);
    for (int i = 0; i < KINS_NUM_AXES; ++i) {
        EXPECT_EQ(kins_pose_get(&p, i), i + 1);
        kins_pose_set(&p, i, -i);
        EXPECT_EQ(kins_pose_get(&p, i), -i);
    }
}

}  // namespace
