/* The Markdown report (docs/peers.md explains every column). */
#include <math.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "table.h"

static void cpu_model(char *buf, size_t n)
{
    snprintf(buf, n, "unknown CPU");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f))
        if (strncmp(line, "model name", 10) == 0) {
            const char *colon = strchr(line, ':');
            if (colon) {
                snprintf(buf, n, "%s", colon + 2);
                buf[strcspn(buf, "\n")] = 0;
            }
            break;
        }
    fclose(f);
}

void table_header(FILE *f, unsigned time_limit)
{
    char when[64], cpu[256];
    const time_t t = time(NULL);
    strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", gmtime(&t));
    cpu_model(cpu, sizeof cpu);
    fprintf(f, "Run on %s, %ld CPUs (%s); time limit %u s per engine and case.\n\n", when,
            sysconf(_SC_NPROCESSORS_ONLN), cpu, time_limit);
}

void table_net_check(FILE *f, const bench_case *c, double devA, double devB)
{
    fprintf(f, "- %s: %s; nets off the exact surfaces by at most %.1e and %.1e\n", c->name,
            c->title, devA, devB);
}

void table_start(FILE *f)
{
    fprintf(f, "\n| case | engine | status | curves | points | length error | time (s) | "
               "distance to surfaces | distance to curve (point) | kappa error (median) | tau error (median) | notes |\n");
    fprintf(f, "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

static const char *status_name(run_status s)
{
    switch (s) {
    case RUN_OK:
        return "ok";
    case RUN_ERROR:
        return "error";
    case RUN_TIMEOUT:
        return "timeout";
    case RUN_CRASH:
        return "crash";
    }
    return "?";
}

/* "-" where there is nothing to show */
static void cell(FILE *f, int shown, double v)
{
    if (shown && !isnan(v))
        fprintf(f, " %.1e |", v);
    else
        fprintf(f, " - |");
}

/* "largest (median)" */
static void error_cell(FILE *f, int shown, double largest, double median)
{
    if (shown)
        fprintf(f, " %.1e (%.0e) |", largest, median);
    else
        fprintf(f, " - |");
}

void table_row(FILE *f, const bench_case *c, const char *engine, const peer_summary *s)
{
    const int ran = s->status == RUN_OK || s->status == RUN_ERROR;
    fprintf(f, "| %s | %s | %s |", c->name, engine, status_name(s->status));
    if (ran)
        fprintf(f, " %d of %d | %d of %d |", s->ncurves, c->expect_curves, s->npoints,
                c->expect_points);
    else
        fprintf(f, " - of %d | - of %d |", c->expect_curves, c->expect_points);
    const double len_err = c->expect_length > 0
                               ? fabs(s->length - c->expect_length) / c->expect_length
                               : s->length;
    cell(f, ran, len_err);
    if (ran)
        fprintf(f, " %.3g (%d) |", s->median_seconds, s->runs);
    else
        fprintf(f, " - |");
    cell(f, ran && s->nsamples + s->npoints > 0, s->max_surface_dist);
    if (c->expect_curves > 0)
        cell(f, ran && s->nsamples > 0, s->max_curve_dist);
    else /* the isolated point found nearest to the exact one */
        cell(f, ran && s->npoints > 0, s->point_err);
    error_cell(f, ran && s->kappa_count > 0, s->max_kappa_err, s->median_kappa_err);
    error_cell(f, ran && s->tau_count > 0, s->max_tau_err, s->median_tau_err);
    char note[sizeof s->note];
    memcpy(note, s->note, sizeof note);
    for (char *p = note; *p; p++)
        if (*p == '|' || *p == '\n')
            *p = ' ';
    if (s->stationary > 0)
        fprintf(f, " %d samples where the parametrisation stands still (no kappa there);",
                s->stationary);
    fprintf(f, " %s |\n", note);
}
