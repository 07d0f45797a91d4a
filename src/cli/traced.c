/* Loading a problem file and tracing it, for the commands that need the
 * whole intersection (trace, plot). */
#include "cli/cli.h"

#include <stdio.h>
#include <unistd.h>

/* Progress of a long trace on a terminal: one line, rewritten. */
static void show_progress(void *user, const char *stage, long done, long total)
{
    int *shown = user;
    fprintf(stderr, "\rintercurve: %s %ld/%ld   ", stage, done, total);
    *shown = 1;
}

int ic_cli_trace_file(const char *file, ic_trace_options *opt, ic_cli_traced *t)
{
    memset(t, 0, sizeof *t);
    const int rc = ic_cli_load_problem(&t->problem, file, 0);
    if (rc != 0)
        return rc;
    ic_error err;
    ic_error_clear(&err);
    file = ic_cli_file_name(file);
    opt->has_box = ic_problem_box(t->problem, opt->box);
    const int self = ic_problem_is_self(t->problem);
    if (ic_pair_new(&t->pair, ic_problem_surface(t->problem, 0),
                    self ? NULL : ic_problem_surface(t->problem, 1), &err) != IC_OK) {
        ic_cli_print_error(file, &err);
        ic_cli_traced_free(t);
        return EXIT_INPUT;
    }
    int shown = 0;
    if (!opt->progress && isatty(STDERR_FILENO)) { /* long runs show they are alive */
        opt->progress = show_progress;
        opt->progress_user = &shown;
    }
    const ic_status st = ic_trace(&t->res, t->pair, opt, &err);
    if (opt->progress == show_progress) {
        opt->progress = NULL;
        opt->progress_user = NULL;
    }
    if (shown) /* the progress line is cleared */
        fprintf(stderr, "\r%60s\r", "");
    if (st != IC_OK) {
        ic_cli_print_error(file, &err);
        ic_cli_traced_free(t);
        return st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
    }
    return 0;
}

void ic_cli_traced_free(ic_cli_traced *t)
{
    ic_trace_result_free(t->res);
    ic_pair_free(t->pair);
    ic_problem_free(t->problem);
    memset(t, 0, sizeof *t);
}
