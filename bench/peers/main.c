/* The peer benchmark (docs/peers.md): intercurve, OpenCASCADE (on the
 * B-spline nets and on the analytic surfaces) and SISL on the same exact
 * cases, each engine and case in its own child process; a Markdown report on
 * stdout. `bench_peers [--timeout S] [--engine NAME] [--case NAME]`. */
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
    {"OCCT B-spline", peer_occt_nurbs},
    {"OCCT analytic", peer_occt_analytic},
    {"SISL", peer_sisl},
};

static int usage(const char *why)
{
    fprintf(stderr, "bench_peers: %s\nusage: bench_peers [--timeout SECONDS] [--engine NAME] "
                    "[--case NAME]\n", why);
    return 2;
}

int main(int argc, char **argv)
{
    unsigned time_limit = DEFAULT_TIME_LIMIT;
    const char *only_engine = NULL, *only_case = NULL;
    for (int i = 1; i < argc; i++) {
        if (i + 1 >= argc)
            return usage("an option without its value");
        if (strcmp(argv[i], "--timeout") == 0) {
            char *end;
            const long v = strtol(argv[++i], &end, 10);
            if (*end || v <= 0 || v > 3600)
                return usage("--timeout takes whole seconds in 1..3600");
            time_limit = (unsigned)v;
        } else if (strcmp(argv[i], "--engine") == 0)
            only_engine = argv[++i];
        else if (strcmp(argv[i], "--case") == 0)
            only_case = argv[++i];
        else
            return usage("unknown option");
    }
    bench_case cases[BENCH_NUM_CASES];
    const int n = bench_cases_build(cases);
    table_header(stdout, time_limit);
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
        if (only_case && strcmp(only_case, cases[i].name) != 0)
            continue;
        for (size_t e = 0; e < sizeof engines / sizeof engines[0]; e++) {
            if (only_engine && strcmp(only_engine, engines[e].name) != 0)
                continue;
            peer_summary sum;
            if (peer_run(&engines[e], &cases[i], time_limit, &sum) != 0) {
                perror("bench_peers: fork");
                return 1;
            }
            table_row(stdout, &cases[i], engines[e].name, &sum);
            fflush(stdout);
        }
    }
    return 0;
}
