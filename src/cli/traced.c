/* Loading a problem file and tracing it, for the commands that need the
 * whole intersection (trace, plot): the library's one copy of pair, trace
 * and fit (src/api/api.h), with the command's progress line and messages. */
#include "cli/cli.h"
#include "api/api.h"

#include <stdio.h>
#include <unistd.h>

/* Progress of a long trace on a terminal: one line, rewritten. */
static void show_progress(void *user, const char *stage, long done, long total)
{
    int *shown = user;
    fprintf(stderr, "\rintercurve: %s %ld/%ld   ", stage, done, total);
    *shown = 1;
}

int ic_cli_trace_file(const char *file, ic_trace_options *opt, double fit_tol, const char *command,
                      ic_cli_traced *t)
{
    memset(t, 0, sizeof *t);
    const int rc = ic_cli_load_problem(&t->problem, file, 0);
    if (rc != 0)
        return rc;
    ic_error err;
    ic_error_clear(&err);
    file = ic_cli_file_name(file);
    int shown = 0;
    const int show = !opt->progress && isatty(STDERR_FILENO); /* long runs show they are alive */
    if (show) {
        opt->progress = show_progress;
        opt->progress_user = &shown;
    }
    ic_api_stage failed;
    const ic_status st =
        ic_api_trace_problem(&t->res, &t->pair, t->problem, opt, fit_tol, &failed, &err);
    if (show) {
        opt->progress = NULL;
        opt->progress_user = NULL;
    }
    if (shown) /* the progress line is cleared */
        fprintf(stderr, "\r%60s\r", "");
    if (st == IC_OK)
        return 0;
    if (failed == IC_API_FIT) /* only for want of memory: the tolerance is positive */
        fprintf(stderr, "intercurve %s: %s\n", command, err.message);
    else
        ic_cli_print_error(file, &err);
    ic_cli_traced_free(t);
    if (failed == IC_API_PAIR)
        return EXIT_INPUT;
    return failed == IC_API_TRACE && st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
}

void ic_cli_traced_free(ic_cli_traced *t)
{
    ic_trace_result_free(t->res);
    ic_pair_free(t->pair);
    ic_problem_free(t->problem);
    memset(t, 0, sizeof *t);
}
