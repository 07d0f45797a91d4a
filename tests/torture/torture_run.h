/* The torture set (tests/torture/NAME.json, truth in tests/truth/torture_truth.txt
 * from gen_torture_truth.py): reading the truth, tracing one case in a child
 * process (a crash, a hang or an overflow trap cannot take the test or the
 * benchmark down with it, and a case that runs too long is killed), and
 * judging the result against the truth. Shared by tests/test_torture.c and
 * bench/bench_torture.c. */
#ifndef IC_TEST_TORTURE_RUN_H
#define IC_TEST_TORTURE_RUN_H

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../harness.h"
#include "intercurve.h"

/* Relative tolerance of the lengths: the docs' promise for arc length
 * (TIER_LENGTH, harness.h; the tracer's truncation error per step is
 * absolute, 1e-10 by default, so on curves of normal size the sum over a
 * few hundred steps stays below it). A case that misses it is a known
 * failure, never a looser tolerance. */
#define TT_LENGTH_TOL TIER_LENGTH
/* Point positions: 1e-8 of the problem's size (the located singular points
 * are Newton/Gauss-Newton solutions good to ~1e-12; 1e-8 leaves room for the
 * conditioning of a problem of that size without accepting a point that is
 * merely near). */
#define TT_POINT_TOL 1e-8

typedef struct {
    double length;
    int closed, tangential;
    char shape[24];
} tt_curve;

typedef struct {
    double xyz[3];
    char type[32];
} tt_point;

typedef struct {
    char name[64];
    char verdict[16]; /* complete, incomplete_ok, incomplete, input_error */
    double size;
    int surface; /* 1: the intersection is a surface (coincident) */
    int ncurves, nclosed;
    tt_curve *curves; /* sorted by length, multiplicities expanded */
    int ncurves_read, cap_curves;
    int npoints;
    tt_point points[8];
    int extra_points;
    int bench_only;
    int known_failure;
    char status[400];
} tt_case;

typedef struct {
    int ncases;
    tt_case *cases;
} tt_truth;

static void tt_chomp(char *s)
{
    size_t n = strlen(s);
    while (n && (s[n - 1] == '\n' || s[n - 1] == '\r' || s[n - 1] == ' '))
        s[--n] = 0;
}

/* Reads the truth file; 0 on success. */
static int tt_read_truth(tt_truth *t, const char *path)
{
    memset(t, 0, sizeof *t);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "%s: %s\n", path, strerror(errno));
        return -1;
    }
    char line[1024];
    tt_case *c = NULL;
    int cap_cases = 0, lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        tt_chomp(line);
        if (!line[0] || line[0] == '#')
            continue;
        if (!strncmp(line, "case ", 5)) {
            if (t->ncases == cap_cases) {
                cap_cases = cap_cases ? 2 * cap_cases : 64;
                t->cases = realloc(t->cases, cap_cases * sizeof *t->cases);
            }
            c = &t->cases[t->ncases++];
            memset(c, 0, sizeof *c);
            snprintf(c->name, sizeof c->name, "%s", line + 5);
            continue;
        }
        if (!c)
            goto bad;
        if (!strncmp(line, "verdict ", 8)) {
            snprintf(c->verdict, sizeof c->verdict, "%s", line + 8);
        } else if (!strncmp(line, "size ", 5)) {
            c->size = strtod(line + 5, NULL);
        } else if (!strcmp(line, "curves surface")) {
            c->surface = 1;
        } else if (!strncmp(line, "curves ", 7)) {
            if (sscanf(line, "curves %d closed %d", &c->ncurves, &c->nclosed) != 2)
                goto bad;
        } else if (!strncmp(line, "curve ", 6)) {
            tt_curve cv;
            char oc[16], kind[16];
            int count = 1;
            const int k =
                sscanf(line, "curve %lf %15s %15s %23s x%d", &cv.length, oc, kind, cv.shape, &count);
            if (k < 4)
                goto bad;
            cv.closed = !strcmp(oc, "closed");
            cv.tangential = !strcmp(kind, "tangential");
            for (int i = 0; i < count; i++) {
                if (c->ncurves_read == c->cap_curves) {
                    c->cap_curves = c->cap_curves ? 2 * c->cap_curves : 16;
                    c->curves = realloc(c->curves, (size_t)c->cap_curves * sizeof *c->curves);
                }
                c->curves[c->ncurves_read++] = cv;
            }
        } else if (!strncmp(line, "point ", 6)) {
            if (c->npoints == 8)
                goto bad;
            tt_point *p = &c->points[c->npoints++];
            if (sscanf(line, "point %lf %lf %lf %31s", &p->xyz[0], &p->xyz[1], &p->xyz[2],
                       p->type) != 4)
                goto bad;
        } else if (!strncmp(line, "extra_points", 12)) {
            c->extra_points = 1;
        } else if (!strcmp(line, "bench_only")) {
            c->bench_only = 1;
        } else if (!strncmp(line, "status ", 7)) {
            snprintf(c->status, sizeof c->status, "%s", line + 7);
            c->known_failure = strncmp(c->status, "pass", 4) != 0;
        } else if (!strcmp(line, "end")) {
            if (!c->surface && c->ncurves_read != c->ncurves) {
                fprintf(stderr, "%s: case %s lists %d curves, says %d\n", path, c->name,
                        c->ncurves_read, c->ncurves);
                goto bad;
            }
            c = NULL;
        } else {
            goto bad;
        }
    }
    fclose(f);
    return 0;
bad:
    fprintf(stderr, "%s:%d: cannot read '%s'\n", path, lineno, line);
    fclose(f);
    return -1;
}

static void tt_free_truth(tt_truth *t)
{
    for (int i = 0; i < t->ncases; i++)
        free(t->cases[i].curves);
    free(t->cases);
    memset(t, 0, sizeof *t);
}

/* ---- one run, in a child process ---- */

enum { TT_OK, TT_LOAD_ERROR, TT_PAIR_ERROR, TT_TRACE_ERROR, TT_CRASHED, TT_TIMEOUT };

typedef struct {
    int stage;
    /* complete: the tracer's own account (tracer_complete); certified: the
     * report's complete, the checker's verdict (docs/tracing.md, "The
     * certificate") */
    int complete, certified, nfailures, uncovered, unproven, proven;
    int ncurves, nspecials;
    double ms; /* wall time of ic_trace */
    char message[300];
    char failure[240]; /* the first failure listed */
} tt_summary;

typedef struct {
    double length;
    int closed, tangential, npoints;
    char shape[24];
    char ends[2][16];
} tt_found_curve;

typedef struct {
    double xyz[3];
    char type[32];
    int approximate;
} tt_found_point;

typedef struct {
    tt_summary s;
    tt_found_curve *curves;
    tt_found_point *points;
} tt_result;

static double tt_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int tt_write_all(int fd, const void *buf, size_t n)
{
    const char *p = buf;
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

/* The child: load, pair, trace with the defaults (as `intercurve trace`
 * does, plus the time limit), and send the summary, the curves and the
 * points down the pipe. */
static void tt_child(int fd, const char *path, double time_limit)
{
    tt_summary s;
    memset(&s, 0, sizeof s);
    ic_error err;
    ic_error_clear(&err);
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.time_limit = time_limit;
    if (ic_problem_load(&p, path, &err) != IC_OK) {
        s.stage = TT_LOAD_ERROR;
    } else {
        opt.has_box = ic_problem_box(p, opt.box);
        const int self = ic_problem_is_self(p);
        if (ic_pair_new(&pair, ic_problem_surface(p, 0), self ? NULL : ic_problem_surface(p, 1),
                        &err) != IC_OK) {
            s.stage = TT_PAIR_ERROR;
        } else {
            const double t0 = tt_now();
            const ic_status st = ic_trace(&res, pair, &opt, &err);
            s.ms = (tt_now() - t0) * 1e3;
            s.stage = st == IC_OK ? TT_OK : TT_TRACE_ERROR;
        }
    }
    if (s.stage != TT_OK) {
        snprintf(s.message, sizeof s.message, "%s%s%s", err.path[0] ? err.path : "",
                 err.path[0] ? ": " : "", err.message);
        s.message[strcspn(s.message, "\n")] = 0; /* the first line, without the caret picture */
    }
    tt_found_curve *cv = NULL;
    tt_found_point *pt = NULL;
    if (res) {
        const ic_trace_report *rep = ic_trace_result_report(res);
        s.complete = rep->tracer_complete;
        s.certified = rep->complete;
        s.nfailures = rep->nfailures;
        s.uncovered = rep->uncovered_cells;
        s.unproven = rep->unproven_cells;
        s.proven = rep->proven;
        if (rep->nfailures > 0)
            snprintf(s.failure, sizeof s.failure, "%s", rep->failures[0]);
        s.ncurves = ic_trace_result_num_curves(res);
        s.nspecials = ic_trace_result_num_specials(res);
        cv = calloc((size_t)s.ncurves + 1, sizeof *cv);
        pt = calloc((size_t)s.nspecials + 1, sizeof *pt);
        for (int i = 0; i < s.ncurves; i++) {
            const ic_trace_curve *c = ic_trace_result_curve(res, i);
            cv[i].length = c->length;
            cv[i].closed = c->closed;
            cv[i].tangential = c->tangential;
            cv[i].npoints = c->npoints;
            snprintf(cv[i].shape, sizeof cv[i].shape, "%s", ic_shape_name(c->shape));
            for (int e = 0; e < 2; e++)
                snprintf(cv[i].ends[e], sizeof cv[i].ends[e], "%s",
                         ic_trace_event_name(c->ends[e]));
        }
        for (int i = 0; i < s.nspecials; i++) {
            const ic_trace_special *sp = ic_trace_result_special(res, i);
            memcpy(pt[i].xyz, sp->xyz, sizeof pt[i].xyz);
            snprintf(pt[i].type, sizeof pt[i].type, "%s", ic_point_type_name(sp->type));
            pt[i].approximate = sp->approximate;
        }
    }
    int bad = tt_write_all(fd, &s, sizeof s);
    if (!bad && s.ncurves)
        bad = tt_write_all(fd, cv, (size_t)s.ncurves * sizeof *cv);
    if (!bad && s.nspecials)
        bad = tt_write_all(fd, pt, (size_t)s.nspecials * sizeof *pt);
    free(cv);
    free(pt);
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_problem_free(p);
    close(fd);
    _exit(bad ? 3 : 0);
}

/* Runs one problem file in a child; kills it after `kill_after` seconds
 * (stage TT_TIMEOUT). The result's arrays are freed by tt_free_result. */
static void tt_run(tt_result *r, const char *path, double time_limit, double kill_after)
{
    memset(r, 0, sizeof *r);
    int fds[2];
    fflush(stdout);
    fflush(stderr);
    if (pipe(fds) != 0) {
        r->s.stage = TT_CRASHED;
        snprintf(r->s.message, sizeof r->s.message, "pipe: %s", strerror(errno));
        return;
    }
    const double t0 = tt_now();
    pid_t pid = fork();
    if (pid < 0) {
        r->s.stage = TT_CRASHED;
        snprintf(r->s.message, sizeof r->s.message, "fork: %s", strerror(errno));
        close(fds[0]);
        close(fds[1]);
        return;
    }
    if (pid == 0) {
        close(fds[0]);
        tt_child(fds[1], path, time_limit);
    }
    close(fds[1]);
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    int timed_out = 0;
    for (;;) {
        const double left = kill_after - (tt_now() - t0);
        if (left <= 0) {
            timed_out = 1;
            break;
        }
        struct pollfd pfd = {fds[0], POLLIN, 0};
        const int pr = poll(&pfd, 1, (int)(left * 1e3) + 1);
        if (pr < 0 && errno == EINTR)
            continue;
        if (pr == 0)
            continue; /* the deadline is checked above */
        if (len == cap) {
            cap *= 2;
            buf = realloc(buf, cap);
        }
        const ssize_t n = read(fds[0], buf + len, cap - len);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        len += (size_t)n;
    }
    close(fds[0]);
    if (timed_out)
        kill(pid, SIGKILL);
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR)
        ;
    if (timed_out) {
        r->s.stage = TT_TIMEOUT;
        snprintf(r->s.message, sizeof r->s.message, "killed after %.0f s", kill_after);
        free(buf);
        return;
    }
    if (len < sizeof r->s || !WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) {
        r->s.stage = TT_CRASHED;
        if (WIFSIGNALED(wstatus))
            snprintf(r->s.message, sizeof r->s.message, "the trace died of signal %d (%s)",
                     WTERMSIG(wstatus), strsignal(WTERMSIG(wstatus)));
        else
            snprintf(r->s.message, sizeof r->s.message, "the child exited with status %d",
                     WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
        free(buf);
        return;
    }
    memcpy(&r->s, buf, sizeof r->s);
    const size_t need = sizeof r->s + (size_t)r->s.ncurves * sizeof *r->curves +
                        (size_t)r->s.nspecials * sizeof *r->points;
    if (len != need) {
        r->s.stage = TT_CRASHED;
        snprintf(r->s.message, sizeof r->s.message, "short answer from the child (%zu of %zu bytes)",
                 len, need);
        r->s.ncurves = r->s.nspecials = 0;
        free(buf);
        return;
    }
    r->curves = calloc((size_t)r->s.ncurves + 1, sizeof *r->curves);
    r->points = calloc((size_t)r->s.nspecials + 1, sizeof *r->points);
    memcpy(r->curves, buf + sizeof r->s, (size_t)r->s.ncurves * sizeof *r->curves);
    memcpy(r->points, buf + sizeof r->s + (size_t)r->s.ncurves * sizeof *r->curves,
           (size_t)r->s.nspecials * sizeof *r->points);
    free(buf);
}

static void tt_free_result(tt_result *r)
{
    free(r->curves);
    free(r->points);
    memset(r, 0, sizeof *r);
}

/* ---- judging ---- */

typedef struct {
    int ok;
    int curves_ok, points_ok;
    double max_rel_length_error; /* NaN when the curve counts differ */
    char why[1600];
} tt_verdict;

static void tt_say(tt_verdict *v, const char *fmt, ...)
{
    size_t n = strlen(v->why);
    if (n + 4 >= sizeof v->why)
        return;
    if (n)
        n += (size_t)snprintf(v->why + n, sizeof v->why - n, "; ");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(v->why + n, sizeof v->why - n, fmt, ap);
    va_end(ap);
}

static int tt_cmp_length(const void *a, const void *b)
{
    const double x = ((const tt_found_curve *)a)->length, y = ((const tt_found_curve *)b)->length;
    return (x > y) - (x < y);
}

/* Curves: the count, the closed count, and, sorted by length on both sides,
 * each length within TT_LENGTH_TOL relative, closed, tangential and the shape. */
static int tt_judge_curves(const tt_case *c, const tt_result *r, tt_verdict *v)
{
    v->max_rel_length_error = NAN;
    if (c->surface)
        return 0; /* no set of curves is a surface */
    const int n = r->s.ncurves;
    int closed = 0;
    for (int i = 0; i < n; i++)
        closed += r->curves[i].closed;
    int ok = 1;
    if (n != c->ncurves) {
        tt_say(v, "%d curves (%d closed), expected %d (%d closed)", n, closed, c->ncurves,
               c->nclosed);
        if (n > 0 && n <= 8) {
            char lens[400] = "";
            size_t k = 0;
            for (int i = 0; i < n && k < sizeof lens - 40; i++)
                k += (size_t)snprintf(lens + k, sizeof lens - k, "%s%.15g%s %s", i ? ", " : "",
                                      r->curves[i].length, r->curves[i].closed ? " closed" : "",
                                      r->curves[i].shape);
            tt_say(v, "lengths %s", lens);
        }
        return 0;
    }
    if (closed != c->nclosed) {
        tt_say(v, "%d closed curves, expected %d", closed, c->nclosed);
        ok = 0;
    }
    tt_found_curve *sorted = malloc(((size_t)n + 1) * sizeof *sorted);
    memcpy(sorted, r->curves, (size_t)n * sizeof *sorted);
    qsort(sorted, (size_t)n, sizeof *sorted, tt_cmp_length);
    /* the truth's curves are written sorted by length */
    double worst = 0;
    int worst_i = -1, nbad_len = 0, nbad_kind = 0, nbad_shape = 0, first_shape = -1,
        first_kind = -1;
    for (int i = 0; i < n; i++) {
        const double L = c->curves[i].length;
        const double e = fabs(sorted[i].length - L) / L;
        if (!(e <= worst) || isnan(e)) {
            worst = isnan(e) ? INFINITY : e;
            worst_i = i;
        }
        nbad_len += !(e <= TT_LENGTH_TOL);
        if (sorted[i].closed != c->curves[i].closed ||
            sorted[i].tangential != c->curves[i].tangential) {
            nbad_kind++;
            if (first_kind < 0)
                first_kind = i;
        }
        if (strcmp(sorted[i].shape, c->curves[i].shape)) {
            nbad_shape++;
            if (first_shape < 0)
                first_shape = i;
        }
    }
    v->max_rel_length_error = worst;
    if (nbad_len) {
        tt_say(v, "%d length(s) off by more than %g relative, worst %.2g (%.15g for %.15g)",
               nbad_len, TT_LENGTH_TOL, worst, sorted[worst_i].length,
               c->curves[worst_i].length);
        ok = 0;
    }
    if (nbad_kind) {
        const int i = first_kind;
        tt_say(v, "%d curve(s) of the wrong kind, e.g. length %.10g: %s %s (ends %s, %s), expected %s %s",
               nbad_kind, sorted[i].length, sorted[i].closed ? "closed" : "open",
               sorted[i].tangential ? "tangential" : "transversal", sorted[i].ends[0],
               sorted[i].ends[1], c->curves[i].closed ? "closed" : "open",
               c->curves[i].tangential ? "tangential" : "transversal");
        ok = 0;
    }
    if (nbad_shape) {
        const int i = first_shape;
        tt_say(v, "%d curve(s) of the wrong shape, e.g. length %.10g: %s, expected %s", nbad_shape,
               sorted[i].length, sorted[i].shape, c->curves[i].shape);
        ok = 0;
    }
    free(sorted);
    return ok;
}

/* Points: every expected point found within TT_POINT_TOL * size, with its
 * type; no other point unless the case allows it. */
static int tt_judge_points(const tt_case *c, const tt_result *r, tt_verdict *v)
{
    int ok = 1;
    const int n = r->s.nspecials;
    char *used = calloc((size_t)n + 1, 1);
    for (int k = 0; k < c->npoints; k++) {
        const tt_point *p = &c->points[k];
        int best = -1;
        double bestd = INFINITY;
        for (int i = 0; i < n; i++) {
            if (used[i])
                continue;
            const double *q = r->points[i].xyz;
            const double d = hypot(hypot(q[0] - p->xyz[0], q[1] - p->xyz[1]), q[2] - p->xyz[2]);
            if (d < bestd) {
                bestd = d;
                best = i;
            }
        }
        if (best < 0) {
            tt_say(v, "no point at (%g, %g, %g) (%s)", p->xyz[0], p->xyz[1], p->xyz[2], p->type);
            ok = 0;
            continue;
        }
        used[best] = 1;
        if (!(bestd <= TT_POINT_TOL * c->size)) {
            tt_say(v, "the point nearest (%g, %g, %g) is %.3g away (tolerance %.3g)", p->xyz[0],
                   p->xyz[1], p->xyz[2], bestd, TT_POINT_TOL * c->size);
            ok = 0;
        }
        if (strcmp(r->points[best].type, p->type)) {
            tt_say(v, "the point near (%g, %g, %g) is a %s%s, expected %s", p->xyz[0], p->xyz[1],
                   p->xyz[2], r->points[best].type,
                   r->points[best].approximate ? " (approximate)" : "", p->type);
            ok = 0;
        }
    }
    int extra = 0, first = -1;
    for (int i = 0; i < n; i++)
        if (!used[i]) {
            extra++;
            if (first < 0)
                first = i;
        }
    if (extra && !c->extra_points) {
        const tt_found_point *q = &r->points[first];
        tt_say(v, "%d unexpected point(s), e.g. a %s at (%.6g, %.6g, %.6g)", extra, q->type,
               q->xyz[0], q->xyz[1], q->xyz[2]);
        ok = 0;
    }
    free(used);
    return ok;
}

/* The whole judgement: curves, points and the verdict (tt_case.verdict). */
static void tt_judge(const tt_case *c, const tt_result *r, tt_verdict *v)
{
    memset(v, 0, sizeof *v);
    v->max_rel_length_error = NAN;
    const tt_summary *s = &r->s;
    if (!strcmp(c->verdict, "input_error")) {
        v->ok = s->stage == TT_LOAD_ERROR;
        if (!v->ok) {
            if (s->stage == TT_OK)
                tt_say(v, "the loader accepted the file (traced: %d curves, complete %d, %d failures)",
                       s->ncurves, s->complete, s->nfailures);
            else
                tt_say(v, "not rejected by the loader: %s", s->message);
        }
        return;
    }
    if (s->stage == TT_TIMEOUT || s->stage == TT_CRASHED) {
        tt_say(v, "%s", s->message);
        return;
    }
    if (s->stage != TT_OK) {
        /* an error from the library is an honest answer where an incomplete
         * one is acceptable */
        v->ok = strcmp(c->verdict, "complete") != 0;
        tt_say(v, "%s: %s",
               s->stage == TT_LOAD_ERROR ? "load error"
               : s->stage == TT_PAIR_ERROR ? "pair error"
                                           : "trace error",
               s->message);
        return;
    }
    v->curves_ok = tt_judge_curves(c, r, v);
    v->points_ok = tt_judge_points(c, r, v);
    const int honest_incomplete = !s->complete && s->nfailures > 0;
    if (s->certified && !(v->curves_ok && v->points_ok && strcmp(c->verdict, "incomplete"))) {
        v->ok = 0; /* a proof of a wrong answer, whatever the verdict expected */
        tt_say(v, "the certificate accepted a wrong answer");
    } else if (!strcmp(c->verdict, "complete")) {
        v->ok = v->curves_ok && v->points_ok && s->complete;
        if (!s->complete)
            tt_say(v, "complete = 0 (expected 1; %d failures listed%s%s)", s->nfailures,
                   s->nfailures ? ", the first: " : "", s->failure);
    } else if (!strcmp(c->verdict, "incomplete_ok")) {
        v->ok = (v->curves_ok && v->points_ok) || honest_incomplete;
        if (!v->ok)
            tt_say(v, s->complete ? "complete = 1 with wrong curves"
                                  : "wrong curves, and no failure listed to say so");
    } else if (!strcmp(c->verdict, "incomplete")) {
        v->ok = honest_incomplete;
        if (!v->ok)
            tt_say(v, s->complete ? "complete = 1 for coincident surfaces"
                                  : "no failure listed: the coincidence is not reported");
    } else {
        tt_say(v, "unknown verdict '%s' in the truth", c->verdict);
    }
}

#endif
