// SPDX-License-Identifier: GPL-2.0-or-later
// motion_pathcheck - checks a path that halsampler captured from motmod's joints
// (tests/motion-tp): two columns, X and Y positions x 1e6, one line per servo period.
// The maths (distances, square roots) lives here rather than in awk because the
// kernel flavor's VM has busybox, whose awk has no sqrt.
//
//   motion_pathcheck square DT VLIM ALIM TOL   the 5 x 5 square from (0,0) to (5,0),
//       (5,5), (0,5), (0,0): per-axis velocity and acceleration limits, the largest
//       distance from the square, whether the path stopped on each corner
//   motion_pathcheck circle DT CX CY R F VLIM ALIM   a full circle about (CX, CY):
//       distance from it, that it went round, the path speed reaches F, axis limits
//
// Prints one "what: yes" / "what: NO (value)" line per check and the final point;
// exits 0 (the expected file decides), 2 on bad usage or input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "number_arg.hpp"

namespace {

struct Point {
    double x, y;
};

[[noreturn]] void usage()
{
    std::fprintf(stderr,
                 "usage: motion_pathcheck square DT VLIM ALIM TOL < samples\n"
                 "       motion_pathcheck circle DT CX CY R F VLIM ALIM < samples\n");
    std::exit(2);
}

double arg(const char* s)
{
    return number_arg("motion_pathcheck", s);
}

std::vector<Point> read_samples()
{
    std::vector<Point> pts;
    char line[256];
    int n = 0;
    while (std::fgets(line, sizeof line, stdin)) {
        ++n;
        double x, y;
        if (std::sscanf(line, "%lf %lf", &x, &y) != 2) {
            std::fprintf(stderr, "motion_pathcheck: line %d: expected two numbers\n", n);
            std::exit(2);
        }
        pts.push_back({x / 1e6, y / 1e6});
    }
    if (pts.size() < 3) {
        std::fprintf(stderr, "motion_pathcheck: %zu samples, need at least 3\n", pts.size());
        std::exit(2);
    }
    return pts;
}

// largest per-axis |velocity| and |acceleration| by finite differences
void axis_limits(const std::vector<Point>& p, double dt, double& vmax, double& amax)
{
    vmax = amax = 0;
    for (size_t i = 1; i < p.size(); ++i) {
        double vx = (p[i].x - p[i - 1].x) / dt, vy = (p[i].y - p[i - 1].y) / dt;
        vmax = std::max({vmax, std::fabs(vx), std::fabs(vy)});
        if (i > 1) {
            double pvx = (p[i - 1].x - p[i - 2].x) / dt, pvy = (p[i - 1].y - p[i - 2].y) / dt;
            amax = std::max({amax, std::fabs(vx - pvx) / dt, std::fabs(vy - pvy) / dt});
        }
    }
}

void verdict(const char* what, bool ok, double value)
{
    if (ok)
        std::printf("%s: yes\n", what);
    else
        std::printf("%s: NO (%g)\n", what, value);
}

void limits(const std::vector<Point>& p, double dt, double vlim, double alim)
{
    double vmax, amax;
    axis_limits(p, dt, vmax, amax);
    char what[64];
    std::snprintf(what, sizeof what, "velocity within %g", vlim);
    verdict(what, vmax <= vlim * (1 + 1e-6), vmax);
    std::snprintf(what, sizeof what, "acceleration within %g", alim);
    verdict(what, amax <= alim * (1 + 1e-4), amax);
}

double seg_dist(Point p, Point a, Point b)
{
    double dx = b.x - a.x, dy = b.y - a.y;
    double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

int square(const std::vector<Point>& p, double dt, double vlim, double alim, double tol)
{
    const Point c[5] = {{0, 0}, {5, 0}, {5, 5}, {0, 5}, {0, 0}};
    double dev = 0;
    double best[3], best_speed[3];
    for (size_t i = 0; i < p.size(); ++i) {
        double d = seg_dist(p[i], c[0], c[1]);
        for (int s = 1; s < 4; ++s)
            d = std::min(d, seg_dist(p[i], c[s], c[s + 1]));
        dev = std::max(dev, d);
        // the sample nearest each corner and the speed there: at a stop the cubic
        // interpolator passes within a fraction of a*dt^2 of the corner, at rest
        double speed = i ? std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y) / dt : 0;
        for (int k = 0; k < 3; ++k) {
            double cd = std::hypot(p[i].x - c[k + 1].x, p[i].y - c[k + 1].y);
            if (i == 0 || cd < best[k]) {
                best[k] = cd;
                best_speed[k] = speed;
            }
        }
    }
    limits(p, dt, vlim, alim);
    char what[64];
    std::snprintf(what, sizeof what, "within %g of the square", tol);
    verdict(what, dev <= tol + 2e-6, dev);
    std::printf("stopped on the corners:");
    for (int k = 0; k < 3; ++k)
        std::printf(" %d", best[k] < 2e-5 && best_speed[k] < 2 * alim * dt);
    std::printf("\nfinal %.6f %.6f\n", p.back().x, p.back().y);
    return 0;
}

int circle(const std::vector<Point>& p, double dt, double cx, double cy, double r, double f,
           double vlim, double alim)
{
    double dev = 0, ymin = cy, ymax = cy, smax = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        dev = std::max(dev, std::fabs(std::hypot(p[i].x - cx, p[i].y - cy) - r));
        ymin = std::min(ymin, p[i].y);
        ymax = std::max(ymax, p[i].y);
        if (i)
            smax = std::max(smax, std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y) / dt);
    }
    verdict("on the circle within 1e-5", dev < 1e-5, dev);
    verdict("went round", ymax > cy + r - 0.01 && ymin < cy - r + 0.01, ymax - ymin);
    char what[64];
    std::snprintf(what, sizeof what, "path speed reaches F %g", f);
    verdict(what, std::fabs(smax - f) < 1e-3, smax);
    double vmax, amax;
    axis_limits(p, dt, vmax, amax);
    std::snprintf(what, sizeof what, "axis velocity within %g", vlim);
    verdict(what, vmax <= vlim * (1 + 1e-6), vmax);
    std::snprintf(what, sizeof what, "axis acceleration within %g", alim);
    verdict(what, amax <= alim * (1 + 1e-4), amax);
    std::printf("final %.6f %.6f\n", p.back().x, p.back().y);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
        usage();
    std::string mode = argv[1];
    if (mode == "square" && argc == 6)
        return square(read_samples(), arg(argv[2]), arg(argv[3]), arg(argv[4]), arg(argv[5]));
    if (mode == "circle" && argc == 9)
        return circle(read_samples(), arg(argv[2]), arg(argv[3]), arg(argv[4]), arg(argv[5]),
                      arg(argv[6]), arg(argv[7]), arg(argv[8]));
    usage();
}
