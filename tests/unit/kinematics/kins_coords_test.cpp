// SPDX-License-Identifier: GPL-2.0-or-later
// coordinates= and kinstype= (kernel/kins/kins_coords.c, kins_coords_fp.c):
// kinematics.md sections 2.3 and 3, trivkins' and gantrykins' mapping.
#include "kins_coords.h"
#include "kins_test_util.hpp"

namespace {

kins_coords parse(const char* letters, int max = KINS_MAX_JOINTS)
{
    kins_coords c{};
    EXPECT_EQ(kins_coords_parse("t", letters, max, &c), 0) << letters;
    return c;
}

TEST(KinsCoords, ReadsLettersInEitherCaseSkippingBlanks)
{
    kins_coords c = parse("x Y\tz a");
    ASSERT_EQ(c.num_joints, 4);
    EXPECT_EQ(c.axis[0], 0);
    EXPECT_EQ(c.axis[1], 1);
    EXPECT_EQ(c.axis[2], 2);
    EXPECT_EQ(c.axis[3], 3);
}

TEST(KinsCoords, RefusesBadLettersTooManyJointsAndEmpty)
{
    kins_coords c{};
    EXPECT_EQ(kins_coords_parse("t", "XYQ", 16, &c), -EINVAL);
    EXPECT_EQ(kins_coords_parse("t", "XYZABCUVWXYZABCUV", 16, &c), -EINVAL);  // 17 joints
    EXPECT_EQ(kins_coords_parse("t", "XYZABCUVWX", 9, &c), -EINVAL);
    EXPECT_EQ(kins_coords_parse("t", "   ", 16, &c), -EINVAL);
    EXPECT_EQ(kins_coords_parse("t", "XYZABCUVWXYZABCUVWXYZABCUVWXYZABC", 64, &c), -EINVAL);  // 33 chars
    EXPECT_EQ(kins_coords_parse("t", "XYZABCUVWXYZABCU", 16, &c), 0);
}

TEST(KinsCoords, TrivialOnlyForXyzabcuvwInOrder)
{
    EXPECT_TRUE(kins_coords_is_trivial(&(const kins_coords&)parse("XYZ")));
    EXPECT_TRUE(kins_coords_is_trivial(&(const kins_coords&)parse("xyzabcuvw")));
    EXPECT_FALSE(kins_coords_is_trivial(&(const kins_coords&)parse("XZ")));
    EXPECT_FALSE(kins_coords_is_trivial(&(const kins_coords&)parse("XYYZ")));
}

TEST(KinsCoords, InverseGivesEveryJointItsLetter)
{
    kins_coords c = parse("XYYZ");
    Joints j{};
    EmcPose p = pose(1, 2, 3);
    kins_coords_inverse(&c, &p, j.data());
    expect_joints_near(j, {1, 2, 2, 3}, 0);

    c = parse("XZ");
    p = pose(4, 0, -2);
    kins_coords_inverse(&c, &p, j.data());
    expect_joints_near(j, {4, -2}, 0);

    c = parse("XYZABCUVW");
    p = pose(1, 2, 3, 4, 5, 6, 7, 8, 9);
    kins_coords_inverse(&c, &p, j.data());
    expect_joints_near(j, {1, 2, 3, 4, 5, 6, 7, 8, 9}, 0);
}

TEST(KinsCoords, ForwardFirstJointWinsForTrivkinsLastForGantrykins)
{
    kins_coords c = parse("XYYZ");
    Joints j = joints({1, 2, 2.5, 3});
    EmcPose p = pose(0, 0, 0);
    kins_coords_forward(&c, KINS_FIRST_JOINT_WINS, j.data(), &p);
    EXPECT_EQ(p.tran.y, 2);
    EXPECT_EQ(p.tran.x, 1);
    EXPECT_EQ(p.tran.z, 3);
    kins_coords_forward(&c, KINS_LAST_JOINT_WINS, j.data(), &p);
    EXPECT_EQ(p.tran.y, 2.5);
}

TEST(KinsCoords, ForwardLeavesUnlistedAxesAlone)
{
    kins_coords c = parse("XYZ");
    Joints j = joints({0.1, -0.2, 0.3});
    EmcPose p = pose(9, 9, 9, 4, 5, 6, 7, 8, 9);
    kins_coords_forward(&c, KINS_FIRST_JOINT_WINS, j.data(), &p);
    expect_pose_near(p, pose(0.1, -0.2, 0.3, 4, 5, 6, 7, 8, 9), 0);
}

TEST(KinsCoords, GantryRoundTripMovesBothJointsOfTheAxis)
{
    kins_coords c = parse("XYYZ");
    Lcg rng{1};
    for (int n = 0; n < 100; ++n) {
        EmcPose p = pose(rng.uniform(-500, 500), rng.uniform(-500, 500), rng.uniform(-500, 500));
        Joints j{};
        kins_coords_inverse(&c, &p, j.data());
        EXPECT_EQ(j[1], j[2]);
        EmcPose back{};
        kins_coords_forward(&c, KINS_LAST_JOINT_WINS, j.data(), &back);
        expect_pose_near(back, p, 0);
    }
}

TEST(KinsType, FirstCharacterChoosesTheType)
{
    KINEMATICS_TYPE t{};
    EXPECT_EQ(kins_kinstype_parse("t", "1", &t), 0);
    EXPECT_EQ(t, KINEMATICS_IDENTITY);
    EXPECT_EQ(kins_kinstype_parse("t", "BOTH", &t), 0);
    EXPECT_EQ(t, KINEMATICS_BOTH);
    EXPECT_EQ(kins_kinstype_parse("t", "b", &t), 0);
    EXPECT_EQ(t, KINEMATICS_BOTH);
    EXPECT_EQ(kins_kinstype_parse("t", "f", &t), 0);
    EXPECT_EQ(t, KINEMATICS_FORWARD_ONLY);
    EXPECT_EQ(kins_kinstype_parse("t", "Inverse", &t), 0);
    EXPECT_EQ(t, KINEMATICS_INVERSE_ONLY);
    EXPECT_EQ(kins_kinstype_parse("t", "x", &t), -EINVAL);
    EXPECT_EQ(kins_kinstype_parse("t", "", &t), -EINVAL);
}

}  // namespace
