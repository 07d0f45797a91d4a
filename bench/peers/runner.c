/* The child process: a hanging or crashing engine (SISL hangs on two of the
 * cases) costs its own row and nothing else. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "runner.h"

static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* In the child: the runs, the score of the last one. */
static void child_runs(const peer_engine *e, const bench_case *c, peer_summary *sum)
{
    double times[PEER_MAX_RUNS], spent = 0.0;
    int runs = 0;
    peer_output out;
    peer_output_clear(&out);
    while (runs < PEER_MAX_RUNS && spent < PEER_REPEAT_BUDGET) {
        peer_output_free(&out);
        double seconds = 0.0;
        if (e->run(c, &out, &seconds) != 0) {
            out.failed = 1;
            break;
        }
        times[runs++] = seconds;
        spent += seconds;
        if (out.failed)
            break;
    }
    peer_summarize(c, &out, sum);
    sum->runs = runs;
    qsort(times, runs, sizeof times[0], compare_doubles);
    sum->median_seconds = runs ? (runs % 2 ? times[runs / 2]
                                           : 0.5 * (times[runs / 2 - 1] + times[runs / 2]))
                               : 0.0;
    peer_output_free(&out);
}

void peer_run_here(const peer_engine *e, const bench_case *c, peer_summary *sum)
{
    memset(sum, 0, sizeof *sum);
    child_runs(e, c, sum);
}

static int write_all(int fd, const void *buf, size_t n)
{
    const char *p = buf;
    while (n > 0) {
        const ssize_t w = write(fd, p, n);
        if (w <= 0)
            return -1;
        p += w, n -= (size_t)w;
    }
    return 0;
}

static size_t read_all(int fd, void *buf, size_t n)
{
    char *p = buf;
    size_t got = 0;
    while (got < n) {
        const ssize_t r = read(fd, p + got, n - got);
        if (r <= 0)
            break;
        got += (size_t)r;
    }
    return got;
}

int peer_run(const peer_engine *e, const bench_case *c, unsigned time_limit,
             peer_summary *sum)
{
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    fflush(NULL); /* the child must not print the parent's buffered output again */
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]), close(fds[1]);
        return -1;
    }
    if (pid == 0) {
        close(fds[0]);
        alarm(time_limit);
        peer_summary mine;
        memset(&mine, 0, sizeof mine);
        child_runs(e, c, &mine);
        _exit(write_all(fds[1], &mine, sizeof mine) == 0 ? 0 : 1);
    }
    close(fds[1]);
    memset(sum, 0, sizeof *sum);
    const size_t got = read_all(fds[0], sum, sizeof *sum);
    close(fds[0]);
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    if (got == sizeof *sum && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0)
        return 0;
    memset(sum, 0, sizeof *sum);
    if (WIFSIGNALED(wstatus) && WTERMSIG(wstatus) == SIGALRM) {
        sum->status = RUN_TIMEOUT;
        snprintf(sum->note, sizeof sum->note, "no answer within %u s", time_limit);
    } else {
        sum->status = RUN_CRASH;
        if (WIFSIGNALED(wstatus))
            snprintf(sum->note, sizeof sum->note, "killed by signal %d (%s)", WTERMSIG(wstatus),
                     strsignal(WTERMSIG(wstatus)));
        else
            snprintf(sum->note, sizeof sum->note, "exit status %d", WEXITSTATUS(wstatus));
    }
    return 0;
}
