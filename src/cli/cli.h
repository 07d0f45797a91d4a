/* Shared pieces of the intercurve command. Exit codes (docs/conventions.md,
 * "Exit status of the command"): 0 success, 1 wrong input, 2 the
 * computation cannot be done. */
#ifndef IC_CLI_H
#define IC_CLI_H

#include <stdio.h>
#include <string.h>

#include "cli/options.h"
#include "intercurve.h"

enum { EXIT_INPUT = 1, EXIT_COMPUTE = 2 };

/* A macro's value as the text of a default in an option table ("1e-11"):
 * the tables take their defaults from include/intercurve/defaults.h. */
#define IC_CLI_TEXT_OF_TOKENS(x) #x
#define IC_CLI_TEXT_OF(x) IC_CLI_TEXT_OF_TOKENS(x)

/* Commands */
int ic_cmd_eval(int argc, char **argv);
int ic_cmd_point(int argc, char **argv);
int ic_cmd_trace(int argc, char **argv);
int ic_cmd_plot(int argc, char **argv);
int ic_cmd_surfaces(int argc, char **argv);
int ic_cmd_verify(int argc, char **argv);
/* `intercurve plot`: runs intercurve-plot with the command's own argv
 * (plot_exec.c); returns only when it cannot, with EXIT_COMPUTE after the
 * reason. */
int ic_cli_exec_plot(char **argv);

/* What messages call the problem file: "<stdin>" for "-", else its name. */
const char *ic_cli_file_name(const char *file);
/* Reads the problem file, or standard input for "-" (ic_problem_read with
 * flags); 0, or EXIT_INPUT after printing the error with the file's name. */
int ic_cli_load_problem(ic_problem **p, const char *file, unsigned flags);
/* Prints an error of the library with its file, path and column. */
void ic_cli_print_error(const char *file, const ic_error *err);

/* A problem file loaded, paired and traced (traced.c). */
typedef struct {
    ic_problem *problem;
    ic_pair *pair;
    ic_trace_result *res;
} ic_cli_traced;
/* 0, or the exit code after printing the error: with the file's name, or
 * for the fit (when fit_tol > 0, the curves' B-splines at fit_tol) with
 * "intercurve COMMAND:"; opt->has_box and box are set from the problem. */
int ic_cli_trace_file(const char *file, ic_trace_options *opt, double fit_tol, const char *command,
                      ic_cli_traced *t);
void ic_cli_traced_free(ic_cli_traced *t);

#endif
