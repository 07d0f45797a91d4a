/* The command line's one option parser: each command describes its options
 * in a table (name, kind of value, range, default, help), and the parser
 * reads argv against it, checks every value, and writes the command's
 * --help from the same table, so the help cannot disagree with what is
 * accepted (docs/cli.md). */
#ifndef IC_CLI_OPTIONS_H
#define IC_CLI_OPTIONS_H

#include <stddef.h>
#include <stdio.h>

typedef enum {
    IC_OPT_FLAG,   /* no value */
    IC_OPT_TEXT,   /* any text: a path, a name */
    IC_OPT_CHOICE, /* one of `choices` */
    IC_OPT_INT,    /* a whole number in lo..hi */
    IC_OPT_REAL,   /* a number, or a formula of constants ("pi/4"), in (lo, hi] */
    IC_OPT_LIST,   /* lo..hi numbers or formulas separated by commas */
    IC_OPT_SIZE    /* WxH: W in lo..hi, H in lo2..hi */
} ic_opt_kind;

/* How often an option must be given. */
typedef enum {
    IC_OPT_OPTIONAL,
    IC_OPT_REQUIRED,
    IC_OPT_ONE_OF /* exactly one of the command's IC_OPT_ONE_OF options */
} ic_opt_need;

typedef struct {
    const char *name;    /* "--order", or "-o" */
    const char *metavar; /* the value's name in the help ("K"); NULL for a flag */
    ic_opt_kind kind;
    double lo, hi;        /* the range (see ic_opt_kind); hi may be INFINITY for REAL */
    double lo2;           /* IC_OPT_SIZE: the least H */
    const char *choices;  /* IC_OPT_CHOICE: "json|text" */
    const char *fallback; /* the default, read as if given; NULL: none */
    ic_opt_need need;
    const char *help; /* what it means; '\n' starts a new line of the help */
} ic_cli_option;

typedef struct {
    const char *name;    /* "trace" */
    const char *file;    /* the file argument in the help: NULL for "PROBLEM.json" */
    const char *summary; /* what the command does, after the usage line */
    const ic_cli_option *options;
    int noptions;
    const char *notes; /* after the options: details and examples */
} ic_cli_command;

/* Longest list a IC_OPT_LIST option holds. */
#define IC_CLI_MAX_LIST 4

/* An option's value after parsing: its default where it was not given. */
typedef struct {
    int given;                    /* 1 when on the command line */
    const char *text;             /* the value as written (NULL for a flag or without one) */
    long integer;                 /* IC_OPT_INT, IC_OPT_FLAG (1 when given) */
    double real;                  /* IC_OPT_REAL */
    double list[IC_CLI_MAX_LIST]; /* IC_OPT_LIST */
    int count;                    /* IC_OPT_LIST: values in list */
    int choice;                   /* IC_OPT_CHOICE: the index in choices */
    int width, height;            /* IC_OPT_SIZE */
} ic_cli_value;

/* What ic_cli_parse returns besides 0 and the exit codes: --help was
 * printed, the command exits 0. */
#define IC_CLI_HELP (-1)

/* Reads argv[1..argc-1] against the command's table: `--opt value`,
 * `--opt=value`, the problem file (`-` for standard input) and `--`, after
 * which every argument is a file. values[i] receives options[i]'s value.
 * Returns 0, IC_CLI_HELP after printing the help (-h, --help anywhere
 * before `--`), or EXIT_INPUT after a message naming the option. */
int ic_cli_parse(const ic_cli_command *cmd, int argc, char **argv, const char **file,
                 ic_cli_value *values);

/* Prints the command's help: usage, summary, every option with its range
 * and default, notes. */
void ic_cli_print_help(const ic_cli_command *cmd, FILE *f);

/* The file argument's name in the help and messages ("PROBLEM.json"). */
const char *ic_cli_file_arg(const ic_cli_command *cmd);

/* Reads one option's value from text into *v; 0, or -1 after a message
 * "intercurve CMD: OPTION ..." on stderr. */
int ic_cli_read_value(const char *cmd, const ic_cli_option *opt, const char *text, ic_cli_value *v);

/* A bound of a range as the help writes it: %g without exponent padding
 * ("0.01", "1e6", "1e-6"). */
void ic_cli_format_bound(char *out, size_t size, double x);

/* "a|b|c" as "a, b, c". */
void ic_cli_choices_text(char *out, size_t size, const char *choices);

#endif
