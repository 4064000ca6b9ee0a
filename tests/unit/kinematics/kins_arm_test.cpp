// SPDX-License-Identifier: GPL-2.0-or-later
// pumakins and genserkins mathematics (kernel/kins/kins_puma_fp.c, kins_genser_fp.c):
// kinematics.md sections 8 and 10.
#include "kins_test_util.hpp"

namespace {

const kins_puma puma{300, 50, 70, 400, 70};

TEST(Pumakins, ForwardVectors)
{
    struct { Joints j; EmcPose w; unsigned long iflags; } rows[] = {
        {joints({0, 0, 0, 0, 0, 0}), pose(350, 70, -470, 180, 0, 0), KINS_PUMA_SINGULAR},
        {joints({10, -20, 30, 15, 25, -40}),
         pose(205.665567, 115.119084, -357.515152, -158.069396, 27.656272, 39.874614), 0},
        {joints({-30, 10, -45, 0, 60, 90}),
         pose(499.403719, -207.501834, -414.517994, 155, 0, -120), 0},
    };
    for (auto& r : rows) {
        EmcPose w{};
        KINEMATICS_INVERSE_FLAGS ifl = 99;
        kins_puma_forward(&puma, r.j.data(), &w, &ifl);
        expect_pose_near(w, r.w, 1e-6);
        EXPECT_EQ(ifl, r.iflags);
    }
}

TEST(Pumakins, InverseVectorsWithTheirFlags)
{
    struct { EmcPose w; unsigned long iflags; Joints want; } rows[] = {
        {pose(205.665567, 115.119084, -357.515152, -158.069396, 27.656272, 39.874614), 0,
         joints({10, -20, 30, 15, 25, -40})},
        {pose(499.403719, -207.501834, -414.517994, 155, 0, -120), 0,
         joints({-30, 10, -45, 0, 60, 90})},
    };
    for (auto& r : rows) {
        Joints j{};
        KINEMATICS_FORWARD_FLAGS ff = 5;
        ASSERT_EQ(kins_puma_inverse(&puma, &r.w, j.data(), r.iflags, &ff), 0);
        EXPECT_EQ(ff, 0u);
        expect_joints_near(j, {r.want[0], r.want[1], r.want[2], r.want[3], r.want[4], r.want[5]},
                           1e-5, true);
    }
}

TEST(Pumakins, SingularWristKeepsTheCurrentJoint3)
{
    EmcPose w = pose(350, 70, -470, 180, 0, 0);
    Joints j = joints({0, 0, 0, 12.5, 0, 0});
    KINEMATICS_FORWARD_FLAGS ff = 0;
    ASSERT_EQ(kins_puma_inverse(&puma, &w, j.data(), KINS_PUMA_SINGULAR, &ff), 0);
    EXPECT_EQ(ff, KINS_PUMA_REACH);
    EXPECT_NEAR(j[3], 12.5, 1e-9);
    EXPECT_NEAR(j[0], 0, 1e-6);
    EXPECT_NEAR(j[1], 0, 1e-6);
    EXPECT_NEAR(j[2], 0, 1e-6);
    EXPECT_NEAR(j[4], 0, 1e-6);
    // θ4 + θ6 is what the pose fixes: 0 here
    EXPECT_NEAR(angle_diff(j[3] + j[5], 0), 0, 1e-6);
}

TEST(Pumakins, RoundTripOverRandomJointsInEveryConfiguration)
{
    Lcg rng{6};
    int checked = 0;
    for (int n = 0; n < 500; ++n) {
        Joints j = joints({rng.uniform(-170, 170), rng.uniform(-80, 80), rng.uniform(-80, 80),
                           rng.uniform(-170, 170), rng.uniform(-120, 120), rng.uniform(-170, 170)});
        if (std::fabs(j[4]) < 2)
            continue;  // the wrist singularity
        EmcPose w{};
        KINEMATICS_INVERSE_FLAGS ifl = 0;
        kins_puma_forward(&puma, j.data(), &w, &ifl);
        Joints back{};
        KINEMATICS_FORWARD_FLAGS ff = 0;
        ASSERT_EQ(kins_puma_inverse(&puma, &w, back.data(), ifl, &ff), 0);
        // the joints of the configuration the forward reported: the same pose
        EmcPose again{};
        KINEMATICS_INVERSE_FLAGS ifl2 = 0;
        kins_puma_forward(&puma, back.data(), &again, &ifl2);
        expect_pose_near(again, w, 1e-6);
        // forward(inverse(x)) = x; and inverse(forward(j)) = j modulo 360
        expect_joints_near(back, {j[0], j[1], j[2], j[3], j[4], j[5]}, 1e-5, true);
        ++checked;
    }
    EXPECT_GT(checked, 400);
}

kins_genser genser_defaults()
{
    kins_genser g{};
    const double a[] = {0, 0, 300, 50, 0, 0};
    const double alpha[] = {0, -KINS_PI / 2, 0, -KINS_PI / 2, KINS_PI / 2, -KINS_PI / 2};
    const double d[] = {0, 0, 70, 400, 0, 0};
    for (int i = 0; i < 6; ++i) {
        g.a[i] = a[i];
        g.alpha[i] = alpha[i];
        g.d[i] = d[i];
    }
    g.max_iterations = 100;
    return g;
}

TEST(Genserkins, ForwardVectors)
{
    kins_genser g = genser_defaults();
    struct { Joints j; EmcPose w; } rows[] = {
        {joints({0, 0, 0, 0, 0, 0}), pose(350, 70, -400, 180, 0, 0)},
        {joints({10, -20, 30, 15, 25, -40}),
         pose(245.557888, 114.378344, -299.999467, -158.069396, 27.656272, 39.874614)},
        {joints({0, -90, 90, 0, 45, 0}), pose(50, 70, -100, 180, 45, 0)},
    };
    for (auto& r : rows) {
        EmcPose w{};
        kins_genser_forward(&g, r.j.data(), &w);
        expect_pose_near(w, r.w, 1e-6);
    }
}

TEST(Genserkins, InverseConvergesFromANearbyEstimate)
{
    kins_genser g = genser_defaults();
    EmcPose w = pose(245.557888, 114.378344, -299.999467, -158.069396, 27.656272, 39.874614,
                     1, 2, 3);
    Joints j = joints({8, -18, 28, 13, 22, -37});
    unsigned iterations = 0;
    ASSERT_EQ(kins_genser_inverse(&g, &w, j.data(), &iterations), 0);
    expect_joints_near(j, {10, -20, 30, 15, 25, -40, 1, 2, 3}, 1e-5);
    EXPECT_LE(iterations, 8u);
}

TEST(Genserkins, InverseFailsAfterMaxIterationsOutOfReach)
{
    kins_genser g = genser_defaults();
    EmcPose w = pose(5000, 0, 0, 180, 0, 0);
    Joints j = joints({1, -10, 20, 1, 20, 1});
    unsigned iterations = 0;
    EXPECT_LT(kins_genser_inverse(&g, &w, j.data(), &iterations), 0);
    g.max_iterations = 0;
    w = pose(350, 70, -400, 180, 0, 0);
    EXPECT_EQ(kins_genser_inverse(&g, &w, j.data(), &iterations), -2);
}

TEST(Genserkins, RoundTripFromPerturbedJoints)
{
    kins_genser g = genser_defaults();
    Lcg rng{7};
    int checked = 0;
    for (int n = 0; n < 200; ++n) {
        Joints j = joints({rng.uniform(-150, 150), rng.uniform(-70, 10), rng.uniform(10, 80),
                           rng.uniform(-150, 150), rng.uniform(10, 110), rng.uniform(-150, 150),
                           rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
        // the wrist centre's reach from the shoulder axis: near 0 the shoulder is
        // singular and Newton may settle on the other shoulder solution
        double s23 = std::sin((j[1] + j[2]) * KINS_DEG), c23 = std::cos((j[1] + j[2]) * KINS_DEG);
        if (std::fabs(300 * std::cos(j[1] * KINS_DEG) + 50 * c23 - 400 * s23) < 100)
            continue;
        EmcPose w{};
        kins_genser_forward(&g, j.data(), &w);
        Joints start = j;
        for (int i = 0; i < 6; ++i)
            start[i] += rng.uniform(-2, 2);
        unsigned it = 0;
        ASSERT_EQ(kins_genser_inverse(&g, &w, start.data(), &it), 0) << "pose " << n;
        EmcPose back{};
        kins_genser_forward(&g, start.data(), &back);
        expect_pose_near(back, w, 1e-6);
        expect_joints_near(start, {j[0], j[1], j[2], j[3], j[4], j[5], j[6], j[7], j[8]}, 1e-5);
        ++checked;
    }
    EXPECT_GT(checked, 120);
}

TEST(Genserkins, UnrotateCouplesAJointToThePreviousOne)
{
    kins_genser g = genser_defaults();
    Joints j = joints({10, -20, 30, 15, 25, -40});
    EmcPose plain{};
    kins_genser_forward(&g, j.data(), &plain);
    g.unrotate[5] = 1;
    Joints coupled = j;
    coupled[5] = j[5] + j[4];  // the same link angle
    EmcPose w{};
    kins_genser_forward(&g, coupled.data(), &w);
    expect_pose_near(w, plain, 1e-9);
    Joints start = joints({9, -19, 29, 14, 24, -14});
    unsigned it = 0;
    ASSERT_EQ(kins_genser_inverse(&g, &w, start.data(), &it), 0);
    expect_joints_near(start, {10, -20, 30, 15, 25, -15}, 1e-5);
}

TEST(Genserkins, SameOrientationAsPumakinsForTheSameJoints)
{
    kins_genser g = genser_defaults();
    Joints j = joints({10, -20, 30, 15, 25, -40});
    EmcPose a{}, b{};
    KINEMATICS_INVERSE_FLAGS ifl;
    kins_genser_forward(&g, j.data(), &a);
    kins_puma_forward(&puma, j.data(), &b, &ifl);
    EXPECT_NEAR(angle_diff(a.a, b.a), 0, 1e-9);
    EXPECT_NEAR(angle_diff(a.b, b.b), 0, 1e-9);
    EXPECT_NEAR(angle_diff(a.c, b.c), 0, 1e-9);
}

}  // namespace
