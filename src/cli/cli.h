/* Shared pieces of the intercurve command. Exit codes (docs/conventions.md,
 * "Exit status of the command"): 0 success, 1 wrong input, 2 the
 * computation cannot be done. */
#ifndef IC_CLI_H
#define IC_CLI_H

#include <cjson/cJSON.h>
#include <stdio.h>
#include <string.h>

#include "intercurve.h"

enum { EXIT_INPUT = 1, EXIT_COMPUTE = 2 };

/* Commands */
int ic_cmd_eval(int argc, char **argv);
int ic_cmd_point(int argc, char **argv);
int ic_cmd_trace(int argc, char **argv);
int ic_cmd_plot(int argc, char **argv);

/* Parses "a,b[,c]" (each a formula of constants, "pi/2") into out[max];
 * returns the count, or -1 with a message on stderr naming `option`. */
int ic_cli_parse_list(double *out, int max, const char *text, const char *option);
/* Parses a whole number in [lo, hi]; -1 with a message on failure. */
int ic_cli_parse_int(int *out, const char *text, int lo, int hi, const char *option);
/* Prints an error of the library with its file, path and column. */
void ic_cli_print_error(const char *file, const ic_error *err);

/* A problem file loaded, paired and traced (traced.c). */
typedef struct {
    ic_problem *problem;
    ic_pair *pair;
    ic_trace_result *res;
} ic_cli_traced;
/* 0, or the exit code after printing the error with the file's name;
 * opt->has_box and box are set from the problem. */
int ic_cli_trace_file(const char *file, ic_trace_options *opt, ic_cli_traced *t);
void ic_cli_traced_free(ic_cli_traced *t);

/* JSON output: arrays of doubles (non-finite values become null). */
cJSON *ic_json_vector(const double *v, int n);
cJSON *ic_json_number_or_null(double x);
/* Prints the document to stdout and frees it; 0 on success. */
int ic_json_print(cJSON *doc);
/* Writes doc (then freed) to f; 0 on success. */
int ic_json_write(FILE *f, cJSON *doc);

#endif
