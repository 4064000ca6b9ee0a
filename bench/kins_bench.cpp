// SPDX-License-Identifier: GPL-2.0-or-later
// kins_bench: the cost of one forward and one inverse kinematics call of each
// kinematics module (ns per call, median of 9 rounds), on the C the modules are built
// from (kernel/kins/kins_*_fp.c), in this process. Prints figures, never fails.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "kins_coords.h"
#include "kins_models.h"

namespace {

using Clock = std::chrono::steady_clock;
volatile double sink;  // keeps the results alive

double ns_per_call(const std::function<void(int)>& call, int n)
{
    std::vector<double> rounds;
    for (int r = 0; r < 9; ++r) {
        auto t0 = Clock::now();
        for (int i = 0; i < n; ++i)
            call(i);
        auto t1 = Clock::now();
        rounds.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / n);
    }
    std::nth_element(rounds.begin(), rounds.begin() + 4, rounds.end());
    return rounds[4];
}

EmcPose pose(double x, double y, double z, double a, double b, double c)
{
    EmcPose p{};
    p.tran = {x, y, z};
    p.a = a;
    p.b = b;
    p.c = c;
    return p;
}

void row(const char* name, double fwd, double inv, const char* note)
{
    std::printf("%-11s forward %8.0f ns   inverse %8.0f ns   %s\n", name, fwd, inv, note);
}

}  // namespace

int main()
{
    const int n = 20000;
    std::array<double, KINS_MAX_JOINTS> j{};
    EmcPose w{};
    KINEMATICS_FORWARD_FLAGS ff = 0;
    KINEMATICS_INVERSE_FLAGS ifl = 0;
    auto wiggle = [](int i) { return 1e-6 * (i & 7); };  // inputs that change a little

    kins_coords coords{};
    kins_coords_parse("bench", "XYYZABC", KINS_MAX_JOINTS, &coords);
    row("trivkins",
        ns_per_call([&](int i) { j[0] = wiggle(i); kins_coords_forward(&coords, KINS_FIRST_JOINT_WINS, j.data(), &w); sink = w.tran.x; }, n),
        ns_per_call([&](int i) { w.tran.x = wiggle(i); kins_coords_inverse(&coords, &w, j.data()); sink = j[0]; }, n),
        "coordinates=XYYZABC (gantrykins: the same mapping)");

    j = {1, 2, 3, 0, 0, 30};
    row("rotatekins",
        ns_per_call([&](int i) { j[0] = 1 + wiggle(i); kins_rotate_forward(j.data(), &w); sink = w.tran.x; }, n),
        ns_per_call([&](int i) { w = pose(1 + wiggle(i), 2, 3, 0, 0, 30); kins_rotate_inverse(&w, j.data()); sink = j[0]; }, n), "");

    kins_tripod tri{10, 5, 8};
    j = {11.874342, 11.874342, 10.770330};
    row("tripodkins",
        ns_per_call([&](int i) { j[0] = 11.874342 + wiggle(i); kins_tripod_forward(&tri, j.data(), &w, 0); sink = w.tran.z; }, n),
        ns_per_call([&](int i) { w = pose(5 + wiggle(i), 4, 10, 0, 0, 0); kins_tripod_inverse(&tri, &w, j.data(), &ff); sink = j[0]; }, n), "");

    kins_max mx{0.666, false};
    j = {0.667, 0.5, -0.289227, 0, 30, 20, 0, 0, 0};
    row("maxkins",
        ns_per_call([&](int i) { j[0] = 0.667 + wiggle(i); kins_max_forward(&mx, j.data(), &w); sink = w.tran.x; }, n),
        ns_per_call([&](int i) { w = pose(1 + wiggle(i), 0.5, -0.2, 0, 30, 20); kins_max_inverse(&mx, &w, j.data()); sink = j[0]; }, n), "");

    kins_scara sc{490, 340, 50, 250, 50, 50};
    j = {30, 45, 100, 10};
    row("scarakins",
        ns_per_call([&](int i) { j[0] = 30 + wiggle(i); kins_scara_forward(&sc, j.data(), &w, &ifl); sink = w.tran.x; }, n),
        ns_per_call([&](int i) { w = pose(363.5 + wiggle(i), 461.3, 390, 0, 0, 85); kins_scara_inverse(&sc, &w, j.data(), 0); sink = j[0]; }, n), "");

    kins_puma pu{300, 50, 70, 400, 70};
    j = {10, -20, 30, 15, 25, -40};
    kins_puma_forward(&pu, j.data(), &w, &ifl);
    EmcPose puma_pose = w;
    row("pumakins",
        ns_per_call([&](int i) { j[0] = 10 + wiggle(i); kins_puma_forward(&pu, j.data(), &w, &ifl); sink = w.tran.x; }, n),
        ns_per_call([&](int i) { w = puma_pose; w.tran.x += wiggle(i); kins_puma_inverse(&pu, &w, j.data(), 0, &ff); sink = j[0]; }, n), "");

    kins_genser gs{};
    const double a[] = {0, 0, 300, 50, 0, 0}, d[] = {0, 0, 70, 400, 0, 0};
    const double al[] = {0, -KINS_PI / 2, 0, -KINS_PI / 2, KINS_PI / 2, -KINS_PI / 2};
    for (int k = 0; k < 6; ++k) {
        gs.a[k] = a[k];
        gs.alpha[k] = al[k];
        gs.d[k] = d[k];
    }
    gs.max_iterations = 100;
    std::array<double, KINS_MAX_JOINTS> jt = {10, -20, 30, 15, 25, -40};
    kins_genser_forward(&gs, jt.data(), &w);
    EmcPose genser_pose = w;
    unsigned it = 0, it_sum = 0;
    double gfwd = ns_per_call([&](int i) { jt[0] = 10 + wiggle(i); kins_genser_forward(&gs, jt.data(), &w); sink = w.tran.x; }, n);
    // inverse from the joints of the previous servo period: 0.01° away on every joint
    double ginv = ns_per_call([&](int i) {
        j = {10.01, -20.01, 30.01, 15.01, 25.01, -40.01};
        w = genser_pose;
        w.tran.x += wiggle(i);
        kins_genser_inverse(&gs, &w, j.data(), &it);
        it_sum += it;
        sink = j[0];
    }, n / 10);
    char note[96];
    std::snprintf(note, sizeof note, "Newton from 0.01 deg away: %.1f iterations",
                  double(it_sum) / (9.0 * (n / 10)));
    row("genserkins", gfwd, ginv, note);

    kins_genhex hx{};
    kins_genhex_defaults(&hx);
    EmcPose hex_pose = pose(1, 2, 20, 5, -3, 10);
    std::array<double, KINS_MAX_JOINTS> js{};
    kins_genhex_inverse(&hx, &hex_pose, js.data(), nullptr);
    it_sum = 0;
    double hfwd = ns_per_call([&](int i) {
        w = pose(1.001, 2.001, 20.001, 5.01, -3.01, 10.01);  // the previous period's pose
        js[0] += wiggle(i) - wiggle(i - 1);
        kins_genhex_forward(&hx, js.data(), &w, &it);
        it_sum += it;
        sink = w.tran.x;
    }, n / 10);
    double hinv = ns_per_call([&](int i) { w = hex_pose; w.tran.x += wiggle(i); kins_genhex_inverse(&hx, &w, js.data(), nullptr); sink = js[0]; }, n);
    std::snprintf(note, sizeof note, "Newton from the previous pose: %.1f iterations",
                  double(it_sum) / (9.0 * (n / 10)));
    row("genhexkins", hfwd, hinv, note);
    return 0;
}
