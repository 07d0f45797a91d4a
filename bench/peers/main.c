/* The peer benchmark (docs/peers.md): intercurve, OpenCASCADE (on the
 * B-spline nets and on the analytic surfaces) and SISL on the same exact
 * cases, each engine and case in its own child process; a Markdown report on
 * stdout. `bench_peers [--timeout S] [--engine NAME] [--case NAME] [--no-fork]`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runner.h"
#include "table.h"

/* the nets must be the exact surfaces to this (length units) before any
 * engine runs */
#define NET_TOLERANCE 1e-14
/* parameter grid of the net check, per direction */
#define NET_CHECK_GRID 64
#define DEFAULT_TIME_LIMIT 60

static const peer_engine engines[] = {
    {"intercurve", peer_intercurve},
    {"intercurve B-spline", peer_intercurve_bspline},
    {"intercurve primitives", peer_intercurve_primitives},
    {"OCCT B-spline", peer_occt_nurbs},
    {"OCCT analytic", peer_occt_analytic},
    {"SISL", peer_sisl},
};

static int usage(const char *what, const char *arg)
{
    fprintf(stderr, "bench_peers: %s%s%s\nusage: bench_peers [--timeout SECONDS] "
                    "[--engine NAME] [--case NAME] [--no-fork]\n",
            what, arg ? ": " : "", arg ? arg : "");
    return 2;
}

typedef struct {
    unsigned time_limit;
    const char *only_engine, *only_case;
    int here; /* --no-fork: every run in this process, no time limit */
} options;

/* Returns 0, or the exit status of a bad command line. */
static int parse_options(int argc, char **argv, options *o)
{
    o->time_limit = DEFAULT_TIME_LIMIT, o->only_engine = o->only_case = NULL, o->here = 0;
    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (strcmp(opt, "--no-fork") == 0) {
            o->here = 1;
            continue;
        }
        if (strcmp(opt, "--timeout") && strcmp(opt, "--engine") && strcmp(opt, "--case"))
            return usage("unknown option", opt);
        if (i + 1 >= argc)
            return usage("no value after", opt);
        const char *value = argv[++i];
        if (strcmp(opt, "--timeout") == 0) {
            char *end;
            const long v = strtol(value, &end, 10);
            if (*end || v <= 0 || v > 3600)
                return usage("--timeout takes whole seconds in 1..3600, not", value);
            o->time_limit = (unsigned)v;
        } else if (strcmp(opt, "--engine") == 0)
            o->only_engine = value;
        else
            o->only_case = value;
    }
    return 0;
}

static int known_engine(const char *name)
{
    for (size_t e = 0; e < sizeof engines / sizeof engines[0]; e++)
        if (strcmp(engines[e].name, name) == 0)
            return 1;
    return 0;
}

static int known_case(const bench_case *cases, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(cases[i].name, name) == 0)
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    options o;
    const int bad = parse_options(argc, argv, &o);
    if (bad)
        return bad;
    if (o.only_engine && !known_engine(o.only_engine))
        return usage("no such engine (intercurve, \"intercurve B-spline\", \"intercurve primitives\", \"OCCT B-spline\", \"OCCT analytic\", SISL)",
                     o.only_engine);
    bench_case cases[BENCH_NUM_CASES];
    const int n = bench_cases_build(cases);
    if (o.only_case && !known_case(cases, n, o.only_case))
        return usage("no such case", o.only_case);
    table_header(stdout, o.time_limit);
    for (int i = 0; i < n; i++) {
        const double devA = net_check(&cases[i].netA, &cases[i].A, NET_CHECK_GRID);
        const double devB = net_check(&cases[i].netB, &cases[i].B, NET_CHECK_GRID);
        table_net_check(stdout, &cases[i], devA, devB);
        if (!(devA <= NET_TOLERANCE && devB <= NET_TOLERANCE)) {
            fprintf(stderr, "bench_peers: the nets of %s are not the exact surfaces\n",
                    cases[i].name);
            return 1;
        }
    }
    table_start(stdout);
    for (int i = 0; i < n; i++) {
        if (o.only_case && strcmp(o.only_case, cases[i].name) != 0)
            continue;
        for (size_t e = 0; e < sizeof engines / sizeof engines[0]; e++) {
            if (o.only_engine && strcmp(o.only_engine, engines[e].name) != 0)
                continue;
            peer_summary sum;
            if (o.here)
                peer_run_here(&engines[e], &cases[i], &sum);
            else if (peer_run(&engines[e], &cases[i], o.time_limit, &sum) != 0) {
                perror("bench_peers: fork");
                return 1;
            }
            table_row(stdout, &cases[i], engines[e].name, &sum);
            fflush(stdout);
        }
    }
    return 0;
}
