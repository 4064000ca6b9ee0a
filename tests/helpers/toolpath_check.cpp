// SPDX-License-Identifier: GPL-2.0-or-later
// toolpath_check - compares the joint positions a machine was sampled at while it
// ran a G-code program with the path the program describes (the demo and
// tests/demo). The path comes from rs274(1)'s canonical calls (STRAIGHT_TRAVERSE,
// STRAIGHT_FEED, ARC_FEED; machine coordinates, X Y Z first), the samples from
// halsampler(1) (one line "X Y Z" per servo period; "overrun" where samples were lost).
// The maths lives here, not in awk: the kernel flavor's VM has busybox, whose awk
// has no sqrt.
//
//   toolpath_check check CANON SAMPLES [TOL]
//       The path starts where the first sample is (the machine's position when the
//       program started) and visits every move's end in order. Prints the number of
//       samples, the tolerance (TOL, else the program's G64 P value, else 0 under
//       G61/G61.1), the largest distance of a sample from the path and where, whether
//       every move end was passed within the tolerance in order, and where the samples
//       end. Exit 0 when everything holds, 1 when not, 2 on bad usage or input.
//   toolpath_check path CANON X Y Z
//       Prints the path from X Y Z as points (arcs as chords within 1 um), one
//       "X Y Z" line each, for plotting.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "number_arg.hpp"

namespace {

struct Vec {
    double v[3];
    double& operator[](int i) { return v[i]; }
    double operator[](int i) const { return v[i]; }
};

Vec operator-(const Vec& a, const Vec& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

// One move of the program: a line, or an arc (helix) about CENTER in the plane of
// axes P0, P1 (axis P2 moves linearly along it), TURN radians (+ counter-clockwise).
struct Move {
    int line;        // program line (rs274's first column)
    bool arc;
    Vec start, end;
    Vec center;      // arcs: plane coordinates in [p0], [p1]
    int p0, p1, p2;  // arcs: the plane's axes and the helix axis
    double turn;     // arcs: signed swept angle
};

[[noreturn]] void usage()
{
    std::fprintf(stderr,
                 "usage: toolpath_check check CANON SAMPLES [TOL]\n"
                 "       toolpath_check path CANON X Y Z\n");
    std::exit(2);
}

[[noreturn]] void bad(const char* file, int line, const char* what)
{
    std::fprintf(stderr, "toolpath_check: %s:%d: %s\n", file, line, what);
    std::exit(2);
}

double number(const char* s)
{
    return number_arg("toolpath_check", s);
}

// The numbers between the parentheses of "NAME(a, b, ...)".
std::vector<double> call_args(const char* open, const char* file, int n)
{
    std::vector<double> args;
    const char* p = open + 1;
    while (*p && *p != ')') {
        char* end = nullptr;
        double v = std::strtod(p, &end);
        if (end == p)
            bad(file, n, "expected a number in the call's arguments");
        args.push_back(v);
        p = end;
        while (*p == ',' || *p == ' ')
            ++p;
    }
    if (*p != ')')
        bad(file, n, "unterminated call");
    return args;
}

struct Program {
    std::vector<Move> moves;  // start of the first = (0 0 0) until set_start()
    bool has_tolerance = false;
    double tolerance = 0;     // of the last SET_MOTION_CONTROL_MODE (G64 P, 0 for G61)
};

// Reads rs274's output: "LINE NAME(args)" per call.
Program read_canon(const char* file)
{
    std::FILE* f = std::fopen(file, "r");
    if (!f) {
        std::fprintf(stderr, "toolpath_check: cannot open %s: %s\n", file, std::strerror(errno));
        std::exit(2);
    }
    Program prog;
    Vec pos{{0, 0, 0}};
    int plane[3] = {0, 1, 2};  // G17 until SELECT_PLANE says otherwise
    char buf[1024];
    int n = 0;
    while (std::fgets(buf, sizeof buf, f)) {
        ++n;
        int line = 0, used = 0;
        char name[64];
        if (std::sscanf(buf, "%d %63[A-Z_0-9]%n", &line, name, &used) != 2 || buf[used] != '(')
            bad(file, n, "expected 'LINE NAME(...)'");
        const char* open = buf + used;
        std::string call = name;
        if (call == "SELECT_PLANE") {
            if (std::strstr(open, "CANON_PLANE_XY"))
                plane[0] = 0, plane[1] = 1, plane[2] = 2;
            else if (std::strstr(open, "CANON_PLANE_YZ"))
                plane[0] = 1, plane[1] = 2, plane[2] = 0;
            else if (std::strstr(open, "CANON_PLANE_XZ"))
                plane[0] = 2, plane[1] = 0, plane[2] = 1;  // G18: Z then X, as ARC_FEED gives them
            else
                bad(file, n, "only the XY, YZ and XZ planes are checked");
        } else if (call == "SET_MOTION_CONTROL_MODE") {
            const char* comma = std::strchr(open, ',');
            if (!comma)
                bad(file, n, "SET_MOTION_CONTROL_MODE without a tolerance");
            prog.tolerance = std::strtod(comma + 1, nullptr);
            prog.has_tolerance = !(std::strstr(open, "CANON_CONTINUOUS") && prog.tolerance <= 0);
        } else if (call == "STRAIGHT_TRAVERSE" || call == "STRAIGHT_FEED" || call == "STRAIGHT_PROBE") {
            auto a = call_args(open, file, n);
            if (a.size() < 3)
                bad(file, n, "a move with fewer than three axes");
            Move m{line, false, pos, {{a[0], a[1], a[2]}}, {}, 0, 0, 0, 0};
            prog.moves.push_back(m);
            pos = m.end;
        } else if (call == "ARC_FEED") {
            auto a = call_args(open, file, n);
            if (a.size() < 8)
                bad(file, n, "ARC_FEED with fewer than eight arguments");
            Move m{line, true, pos, {{a[5], a[6], a[7]}}, {}, plane[0], plane[1], plane[2], 0};
            m.center[m.p0] = a[2];
            m.center[m.p1] = a[3];
            int rot = static_cast<int>(a[4]);
            if (rot == 0)
                bad(file, n, "ARC_FEED with rotation 0");
            double a0 = std::atan2(m.start[m.p1] - m.center[m.p1], m.start[m.p0] - m.center[m.p0]);
            double a1 = std::atan2(m.end[m.p1] - m.center[m.p1], m.end[m.p0] - m.center[m.p0]);
            double d = a1 - a0;
            // counter-clockwise: 0 < d <= 2 pi (a full circle when the ends meet)
            if (rot > 0) {
                while (d <= 1e-12)
                    d += 2 * M_PI;
                m.turn = d + 2 * M_PI * (rot - 1);
            } else {
                while (d >= -1e-12)
                    d -= 2 * M_PI;
                m.turn = d - 2 * M_PI * (-rot - 1);
            }
            prog.moves.push_back(m);
            pos = m.end;
        } else if (call == "RIGID_TAP") {
            bad(file, n, "RIGID_TAP is not checked");
        }
    }
    std::fclose(f);
    if (prog.moves.empty())
        bad(file, n, "the program makes no move");
    return prog;
}

// The point at fraction t (0..1) along an arc.
Vec arc_point(const Move& m, double t)
{
    double r0 = std::hypot(m.start[m.p0] - m.center[m.p0], m.start[m.p1] - m.center[m.p1]);
    double r1 = std::hypot(m.end[m.p0] - m.center[m.p0], m.end[m.p1] - m.center[m.p1]);
    double a0 = std::atan2(m.start[m.p1] - m.center[m.p1], m.start[m.p0] - m.center[m.p0]);
    double r = r0 + (r1 - r0) * t, a = a0 + m.turn * t;
    Vec p;
    p[m.p0] = m.center[m.p0] + r * std::cos(a);
    p[m.p1] = m.center[m.p1] + r * std::sin(a);
    p[m.p2] = m.start[m.p2] + (m.end[m.p2] - m.start[m.p2]) * t;
    return p;
}

double segment_distance(const Vec& p, const Vec& a, const Vec& b)
{
    Vec d = b - a;
    double len2 = dot(d, d);
    double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    Vec q{{a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]}};
    return norm(p - q);
}

// Distance from P to an arc: the nearest of the points where the sweep passes P's
// angle (the helix axis and radius taken there), or the ends.
double arc_distance(const Vec& p, const Move& m)
{
    double best = std::min(norm(p - m.start), norm(p - m.end));
    double a0 = std::atan2(m.start[m.p1] - m.center[m.p1], m.start[m.p0] - m.center[m.p0]);
    double ap = std::atan2(p[m.p1] - m.center[m.p1], p[m.p0] - m.center[m.p0]);
    double d = ap - a0;
    if (m.turn > 0)
        d = std::fmod(std::fmod(d, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
    else
        d = -std::fmod(std::fmod(-d, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
    for (; std::fabs(d) <= std::fabs(m.turn); d += m.turn > 0 ? 2 * M_PI : -2 * M_PI)
        best = std::min(best, norm(p - arc_point(m, d / m.turn)));
    return best;
}

double move_distance(const Vec& p, const Move& m)
{
    return m.arc ? arc_distance(p, m) : segment_distance(p, m.start, m.end);
}

// halsampler's lines; "overrun" lines are counted.
std::vector<Vec> read_samples(const char* file, int& overruns)
{
    std::FILE* f = std::fopen(file, "r");
    if (!f) {
        std::fprintf(stderr, "toolpath_check: cannot open %s: %s\n", file, std::strerror(errno));
        std::exit(2);
    }
    std::vector<Vec> s;
    char buf[256];
    int n = 0;
    overruns = 0;
    while (std::fgets(buf, sizeof buf, f)) {
        ++n;
        Vec v;
        if (std::strncmp(buf, "overrun", 7) == 0)
            ++overruns;
        else if (std::sscanf(buf, "%lf %lf %lf", &v[0], &v[1], &v[2]) == 3)
            s.push_back(v);
        else
            bad(file, n, "expected three numbers");
    }
    std::fclose(f);
    if (s.size() < 2)
        bad(file, n, "fewer than two samples");
    return s;
}

void set_start(Program& prog, const Vec& start)
{
    prog.moves.front().start = start;
}

// How far the chord from sample I to I+1 may lie inside the curve the machine ran:
// a curve sampled every dt with normal acceleration a has chords a*dt^2/8 inside it,
// and |s[i-1] - 2 s[i] + s[i+1]| is a*dt^2 there. (A blend arc passes a corner at
// exactly the tolerance, so the chords pass it slightly farther.)
double sagitta(const std::vector<Vec>& s, size_t i)
{
    double worst = 0;
    for (size_t k = std::max<size_t>(i, 1); k <= i + 1 && k + 1 < s.size(); ++k) {
        Vec d2{{s[k - 1][0] - 2 * s[k][0] + s[k + 1][0], s[k - 1][1] - 2 * s[k][1] + s[k + 1][1],
                s[k - 1][2] - 2 * s[k][2] + s[k + 1][2]}};
        worst = std::max(worst, norm(d2) / 8);
    }
    return worst;
}

// Index of the first sample segment at or after FROM passing within TOL of P, or -1.
long visit(const std::vector<Vec>& s, size_t from, const Vec& p, double tol)
{
    for (size_t i = from; i + 1 < s.size(); ++i)
        if (segment_distance(p, s[i], s[i + 1]) - sagitta(s, i) <= tol)
            return static_cast<long>(i);
    return -1;
}

int check(const char* canon, const char* samples, const char* tol_arg)
{
    Program prog = read_canon(canon);
    int overruns = 0;
    std::vector<Vec> s = read_samples(samples, overruns);
    set_start(prog, s.front());
    if (!tol_arg && !prog.has_tolerance) {
        std::fprintf(stderr, "toolpath_check: %s: the program sets no path tolerance (G64 P, G61): "
                             "give TOL\n", canon);
        return 2;
    }
    // rs274 prints positions with 4 decimals (halsampler with 6): 0.1 um of rounding
    const double slack = 1e-4;
    double tol = tol_arg ? number(tol_arg) : prog.tolerance;
    std::printf("samples: %zu, overruns: %d\n", s.size(), overruns);
    std::printf("tolerance: %g mm\n", tol);

    double dev = 0;
    size_t worst = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        double d = move_distance(s[i], prog.moves[0]);
        for (size_t k = 1; k < prog.moves.size() && d > 0; ++k)
            d = std::min(d, move_distance(s[i], prog.moves[k]));
        if (d > dev)
            dev = d, worst = i;
    }
    bool ok = overruns == 0;
    std::printf("max deviation: %.6f mm at sample %zu (%.6f %.6f %.6f)\n", dev, worst, s[worst][0],
                s[worst][1], s[worst][2]);
    bool within = dev <= tol + slack;
    std::printf("within tolerance: %s\n", within ? "yes" : "NO");
    ok = ok && within;

    // every move's end, in program order: corners are cut by at most the tolerance
    size_t from = 0;
    int missed = 0;
    for (const Move& m : prog.moves) {
        long at = visit(s, from, m.end, tol + slack);
        if (at < 0) {
            if (!missed++)
                std::printf("not visited: the end of line %d (%.4f %.4f %.4f)\n", m.line, m.end[0],
                            m.end[1], m.end[2]);
            continue;
        }
        from = static_cast<size_t>(at);
    }
    std::printf("move ends visited in order: %zu of %zu\n", prog.moves.size() - missed, prog.moves.size());
    ok = ok && missed == 0;
    const Vec& last = s.back();
    bool at_end = norm(last - prog.moves.back().end) <= slack;
    std::printf("ends at the program's last point: %s (%.6f %.6f %.6f)\n", at_end ? "yes" : "NO",
                last[0], last[1], last[2]);
    ok = ok && at_end;
    std::printf("path check: %s\n", ok ? "passed" : "FAILED");
    return ok ? 0 : 1;
}

int path(const char* canon, const Vec& start)
{
    Program prog = read_canon(canon);
    set_start(prog, start);
    std::printf("%.6f %.6f %.6f\n", start[0], start[1], start[2]);
    for (const Move& m : prog.moves) {
        if (m.arc) {
            // chord error r (1 - cos(step/2)) <= 1 um
            double r = std::hypot(m.start[m.p0] - m.center[m.p0], m.start[m.p1] - m.center[m.p1]);
            double step = r > 1e-3 ? 2 * std::acos(1 - 1e-3 / r) : M_PI / 8;
            int n = std::max(1, static_cast<int>(std::ceil(std::fabs(m.turn) / step)));
            for (int i = 1; i < n; ++i) {
                Vec p = arc_point(m, static_cast<double>(i) / n);
                std::printf("%.6f %.6f %.6f\n", p[0], p[1], p[2]);
            }
        }
        std::printf("%.6f %.6f %.6f\n", m.end[0], m.end[1], m.end[2]);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc >= 4 && argc <= 5 && std::strcmp(argv[1], "check") == 0)
        return check(argv[2], argv[3], argc == 5 ? argv[4] : nullptr);
    if (argc == 6 && std::strcmp(argv[1], "path") == 0)
        return path(argv[2], {{number(argv[3]), number(argv[4]), number(argv[5])}});
    usage();
}
