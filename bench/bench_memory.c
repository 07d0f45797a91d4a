/* Peak memory and time of whole traces (make bench): each bundled example
 * traced, its curves fitted and its JSON document written, as `intercurve
 * trace` does, in a child process of its own, whose peak resident set size
 * (getrusage through wait4: the kernel's high-water mark, in KiB) and wall
 * time are reported (usage: bench_memory EXAMPLES_DIR). */
#define _DEFAULT_SOURCE
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "intercurve.h"


/* The child: 0 when the example was traced, fitted and written. */
static int trace_one(const char *path)
{
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    ic_status st = ic_problem_load(&p, path, NULL);
    if (st == IC_OK) {
        opt.has_box = ic_problem_box(p, opt.box);
        st = ic_pair_new(&pair, ic_problem_surface(p, 0),
                         ic_problem_is_self(p) ? NULL : ic_problem_surface(p, 1), NULL);
    }
    if (st == IC_OK)
        st = ic_trace(&res, pair, &opt, NULL);
    if (st == IC_OK)
        st = ic_trace_fit(res, pair, IC_TRACE_FIT_TOL_DEFAULT, NULL);
    FILE *sink = fopen("/dev/null", "w");
    if (st == IC_OK && sink)
        st = ic_trace_write_json(sink, res, pair, NULL);
    if (sink)
        fclose(sink);
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_problem_free(p);
    return st == IC_OK ? 0 : 1;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "examples";
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "bench_memory: cannot open %s\n", dir);
        return 2;
    }
    char *names[256];
    int n = 0;
    for (struct dirent *e; n < 256 && (e = readdir(d));) {
        const size_t len = strlen(e->d_name);
        if (len > 5 && strcmp(e->d_name + len - 5, ".json") == 0)
            names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, by_name);
    printf("whole traces, each in its own process: traced, fitted, JSON written\n");
    printf("%-32s %12s %12s\n", "example", "peak RSS", "wall time");
    for (int i = 0; i < n; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        const double t0 = now();
        const pid_t pid = fork();
        if (pid == 0)
            _exit(trace_one(path));
        int status = 0;
        struct rusage ru;
        if (pid < 0 || wait4(pid, &status, 0, &ru) != pid) {
            printf("%-32s %12s\n", names[i], "no process");
            continue;
        }
        const double t = now() - t0;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
            printf("%-32s %12s\n", names[i], "failed");
        else
            printf("%-32s %9ld KiB %9.1f ms\n", names[i], ru.ru_maxrss, 1e3 * t);
        free(names[i]);
    }
    return 0;
}
