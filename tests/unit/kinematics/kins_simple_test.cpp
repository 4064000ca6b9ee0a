// SPDX-License-Identifier: GPL-2.0-or-later
// rotatekins, tripodkins, maxkins and scarakins mathematics (kernel/kins/kins_*_fp.c):
// kinematics.md sections 4, 5, 7 and 9.
#include "kins_test_util.hpp"

namespace {

TEST(Rotatekins, InverseVectors)
{
    struct { EmcPose w; double j0, j1; } rows[] = {
        {pose(1, 0, 0, 0, 0, 90), 0, 1},
        {pose(2, 1, 0, 0, 0, 30), 1.232051, 1.866025},
        {pose(10, -5, 0, 0, 0, -45), 3.535534, -10.606602},
    };
    for (auto& r : rows) {
        Joints j{};
        kins_rotate_inverse(&r.w, j.data());
        EXPECT_NEAR(j[0], r.j0, 1e-6);
        EXPECT_NEAR(j[1], r.j1, 1e-6);
        EXPECT_EQ(j[5], r.w.c);
    }
}

TEST(Rotatekins, RoundTripsEverywhere)
{
    Lcg rng{2};
    for (int n = 0; n < 200; ++n) {
        EmcPose w = pose(rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100),
                         rng.uniform(-90, 90), rng.uniform(-90, 90), rng.uniform(-360, 360),
                         rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
        Joints j{};
        kins_rotate_inverse(&w, j.data());
        EmcPose back{};
        kins_rotate_forward(j.data(), &back);
        expect_pose_near(back, w, 1e-9);
    }
}

TEST(Tripodkins, InverseAndForwardVectors)
{
    struct { kins_tripod g; EmcPose d; double j[3]; } rows[] = {
        {{1, 1, 1}, pose(0.2, 0.3, 0.9), {0.969536, 1.240967, 1.392839}},
        {{10, 5, 8}, pose(5, 4, 10), {11.874342, 11.874342, 10.770330}},
    };
    for (auto& r : rows) {
        Joints j{};
        KINEMATICS_FORWARD_FLAGS ff = 7;
        ASSERT_EQ(kins_tripod_inverse(&r.g, &r.d, j.data(), &ff), 0);
        EXPECT_EQ(ff, 0u);
        expect_joints_near(j, {r.j[0], r.j[1], r.j[2]}, 1e-6);
        EmcPose back = pose(0, 0, 0, 1, 2, 3);
        ASSERT_EQ(kins_tripod_forward(&r.g, j.data(), &back, 0), 0);
        expect_pose_near(back, r.d, 1e-9);
    }
}

TEST(Tripodkins, BelowThePlaneNeedsTheFlag)
{
    kins_tripod g{10, 5, 8};
    EmcPose d = pose(3, 2, -4);
    Joints j{};
    KINEMATICS_FORWARD_FLAGS ff = 0;
    ASSERT_EQ(kins_tripod_inverse(&g, &d, j.data(), &ff), 0);
    EXPECT_EQ(ff, KINS_TRIPOD_BELOW);
    EmcPose back{};
    ASSERT_EQ(kins_tripod_forward(&g, j.data(), &back, ff), 0);
    expect_pose_near(back, d, 1e-9);
    ASSERT_EQ(kins_tripod_forward(&g, j.data(), &back, 0), 0);
    EXPECT_NEAR(back.tran.z, 4, 1e-9);
}

TEST(Tripodkins, RefusesDegenerateGeometryAndImpossibleLengths)
{
    Joints j = joints({1, 1, 1});
    EmcPose w{};
    kins_tripod coincide{0, 1, 1}, collinear{1, 1, 0}, ok{1, 1, 1};
    EXPECT_EQ(kins_tripod_forward(&coincide, j.data(), &w, 0), -1);
    EXPECT_EQ(kins_tripod_forward(&collinear, j.data(), &w, 0), -1);
    Joints bad = joints({1, 5, 1});  // |AD| + |AB| < |BD|
    EXPECT_EQ(kins_tripod_forward(&ok, bad.data(), &w, 0), -1);
}

TEST(Tripodkins, RoundTripsAboveAndBelow)
{
    kins_tripod g{10, 5, 8};
    Lcg rng{3};
    for (int n = 0; n < 200; ++n) {
        EmcPose d = pose(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20));
        if (std::fabs(d.tran.z) < 0.1)
            continue;  // the singular plane
        Joints j{};
        KINEMATICS_FORWARD_FLAGS ff = 0;
        kins_tripod_inverse(&g, &d, j.data(), &ff);
        EmcPose back{};
        ASSERT_EQ(kins_tripod_forward(&g, j.data(), &back, ff), 0);
        expect_pose_near(back, d, 1e-7);
    }
}

TEST(Maxkins, InverseVectors)
{
    kins_max g{0.666, false};
    struct { EmcPose w; double j[3]; } rows[] = {
        {pose(1, 0, 0), {1, 0, 0}},
        {pose(1, 0.5, -0.2, 0, 30, 0), {0.667, 0.5, -0.289227}},
        {pose(2, -1, 0.3, 0, -45, 0, 0, 0, 0.2), {2.612354, -1, 0.246354}},
        {pose(1, 0.5, -0.2, 0, 0, 90), {0.5, -1, -0.2}},
        {pose(3, 2, 1, 0, 0, -30, 0, 0, 0.5), {1.598076, 3.232051, 1.5}},
        {pose(1, 1, 0, 0, 10, 0, 0, 0.25, 0), {0.884350, 1.25, -0.010118}},
        {pose(1, 0.5, -0.2, 0, 30, 90), {0.167, -1, -0.289227}},
        {pose(1, 0.5, -0.2, 0, 30, 90, 0.1), {0.253603, -1, -0.239227}},
    };
    for (auto& r : rows) {
        Joints j{};
        kins_max_inverse(&g, &r.w, j.data());
        expect_joints_near(j, {r.j[0], r.j[1], r.j[2]}, 1e-6);
        EXPECT_EQ(j[4], r.w.b);
        EXPECT_EQ(j[5], r.w.c);
        EmcPose back{};
        kins_max_forward(&g, j.data(), &back);
        expect_pose_near(back, r.w, 1e-9);  // also where LinuxCNC's forward is off
    }
}

TEST(Maxkins, ConventionalDirections)
{
    kins_max g{0.666, true};
    EmcPose w = pose(1, 0.5, -0.2, 0, 30, 0);
    Joints j{};
    kins_max_inverse(&g, &w, j.data());
    expect_joints_near(j, {1.333, 0.5, -0.289227}, 1e-6);
}

TEST(Maxkins, RoundTripsOverRandomPoses)
{
    Lcg rng{4};
    for (bool conv : {false, true}) {
        kins_max g{0.666, conv};
        for (int n = 0; n < 200; ++n) {
            EmcPose w = pose(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5), 0,
                             rng.uniform(-90, 90), rng.uniform(-360, 360), rng.uniform(-1, 1),
                             rng.uniform(-1, 1), rng.uniform(-1, 1));
            Joints j{};
            kins_max_inverse(&g, &w, j.data());
            EmcPose back{};
            kins_max_forward(&g, j.data(), &back);
            expect_pose_near(back, w, 1e-9);
        }
    }
}

const kins_scara scara{490, 340, 50, 250, 50, 50};

TEST(Scarakins, ForwardVectors)
{
    struct { Joints j; EmcPose w; } rows[] = {
        {joints({0, 0, 0, 0}), pose(640, 0, 490, 0, 0, 0)},
        {joints({30, 45, 100, 10}), pose(363.511186, 461.291191, 390, 0, 0, 85)},
        {joints({30, -45, 100, 10}), pose(585.739829, 100.937452, 390, 0, 0, -5)},
        {joints({-60, 120, 20, -30}), pose(338.301270, -52.942286, 470, 0, 0, 30)},
    };
    for (auto& r : rows) {
        EmcPose w{};
        KINEMATICS_INVERSE_FLAGS ifl = 9;
        kins_scara_forward(&scara, r.j.data(), &w, &ifl);
        expect_pose_near(w, r.w, 1e-6);
        EXPECT_EQ(ifl, r.j[1] < 0 ? KINS_SCARA_ELBOW_NEGATIVE : 0u);
    }
}

TEST(Scarakins, InverseVectorsForBothElbows)
{
    struct { EmcPose w; double e0[4], e1[4]; } rows[] = {
        {pose(640, 0, 490), {0, 0, 0, 0}, {0, 0, 0, 0}},
        {pose(363.511186, 461.291191, 390, 0, 0, 85), {30, 45, 100, 10}, {67.769131, -45, 100, 62.230869}},
        {pose(585.739829, 100.937452, 390, 0, 0, -5), {-7.769131, 45, 100, -42.230869}, {30, -45, 100, 10}},
        {pose(338.301270, -52.942286, 470, 0, 0, 30), {-60, 120, 20, -30}, {30.400027, -120, 20, 119.599973}},
    };
    for (auto& r : rows) {
        Joints j{};
        kins_scara_inverse(&scara, &r.w, j.data(), 0);
        expect_joints_near(j, {r.e0[0], r.e0[1], r.e0[2], r.e0[3]}, 1e-5, true);
        kins_scara_inverse(&scara, &r.w, j.data(), KINS_SCARA_ELBOW_NEGATIVE);
        expect_joints_near(j, {r.e1[0], r.e1[1], r.e1[2], r.e1[3]}, 1e-5, true);
    }
}

TEST(Scarakins, InverseOfForwardKeepsTheElbow)
{
    Lcg rng{5};
    for (int n = 0; n < 300; ++n) {
        Joints j = joints({rng.uniform(-170, 170), rng.uniform(-175, 175), rng.uniform(0, 200),
                           rng.uniform(-170, 170), rng.uniform(-30, 30), rng.uniform(-30, 30)});
        if (std::fabs(j[1]) < 1)
            continue;  // the straight arm is singular
        EmcPose w{};
        KINEMATICS_INVERSE_FLAGS ifl = 0;
        kins_scara_forward(&scara, j.data(), &w, &ifl);
        Joints back{};
        kins_scara_inverse(&scara, &w, back.data(), ifl);
        expect_joints_near(back, {j[0], j[1], j[2], j[3], j[4], j[5]}, 1e-6, true);
    }
}

TEST(Scarakins, OutOfReachClampsToTheStraightArm)
{
    EmcPose w = pose(1000, 0, 490);
    Joints j{};
    kins_scara_inverse(&scara, &w, j.data(), 0);
    EXPECT_NEAR(j[1], 0, 1e-9);
    EXPECT_TRUE(std::isfinite(j[0]));
}

}  // namespace
