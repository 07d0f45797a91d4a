/* The one option parser of every command (options.h). */
#include "cli/options.h"

#include <string.h>

#include "cli/cli.h"

/* -h or --help before `--`: the help wins over every other argument. */
static int wants_help(int argc, char **argv)
{
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return 1;
    return 0;
}

/* The index of the option named by the first len bytes of arg, or -1. */
static int find_option(const ic_cli_command *cmd, const char *arg, size_t len)
{
    for (int k = 0; k < cmd->noptions; k++)
        if (strlen(cmd->options[k].name) == len && strncmp(cmd->options[k].name, arg, len) == 0)
            return k;
    return -1;
}

static int input_error(const ic_cli_command *cmd)
{
    fprintf(stderr, "try 'intercurve %s --help'\n", cmd->name);
    return EXIT_INPUT;
}

/* One option at argv[*i] (its value at argv[*i + 1] or after '='). */
static int read_option(const ic_cli_command *cmd, int argc, char **argv, int *i,
                       ic_cli_value *values)
{
    const char *arg = argv[*i], *eq = strchr(arg, '=');
    const int k = find_option(cmd, arg, eq ? (size_t)(eq - arg) : strlen(arg));
    if (k < 0) {
        fprintf(stderr, "intercurve %s: unknown option '%.*s'\n", cmd->name,
                eq ? (int)(eq - arg) : (int)strlen(arg), arg);
        return input_error(cmd);
    }
    const ic_cli_option *opt = &cmd->options[k];
    const char *text = NULL;
    if (opt->kind == IC_OPT_FLAG) {
        if (eq) {
            fprintf(stderr, "intercurve %s: %s takes no value, got '%s'\n", cmd->name, opt->name,
                    eq + 1);
            return input_error(cmd);
        }
    } else if (eq) {
        text = eq + 1;
    } else if (*i + 1 < argc) {
        text = argv[++*i];
    } else {
        fprintf(stderr, "intercurve %s: %s needs a value %s\n", cmd->name, opt->name, opt->metavar);
        return input_error(cmd);
    }
    if (ic_cli_read_value(cmd->name, opt, text, &values[k]) < 0)
        return input_error(cmd);
    values[k].given = 1;
    return 0;
}

/* The defaults of the options not given, read as if given. */
static int fill_defaults(const ic_cli_command *cmd, ic_cli_value *values)
{
    for (int k = 0; k < cmd->noptions; k++)
        if (!values[k].given && cmd->options[k].fallback &&
            ic_cli_read_value(cmd->name, &cmd->options[k], cmd->options[k].fallback, &values[k]) <
                0)
            return EXIT_INPUT; /* a wrong table: the tests of --help catch it */
    return 0;
}

/* "one of --at or --params" into out; the number of such options. */
static int one_of_text(char *out, size_t size, const ic_cli_command *cmd)
{
    int n = 0, total = 0;
    for (int k = 0; k < cmd->noptions; k++)
        total += cmd->options[k].need == IC_OPT_ONE_OF;
    size_t used = (size_t)snprintf(out, size, "one of");
    for (int k = 0; k < cmd->noptions && used < size; k++) {
        if (cmd->options[k].need != IC_OPT_ONE_OF)
            continue;
        n++;
        used += (size_t)snprintf(out + used, size - used, "%s %s",
                                 n == 1       ? ""
                                 : n == total ? " or"
                                              : ",",
                                 cmd->options[k].name);
    }
    return total;
}

/* The problem file, the required options and exactly one of the ONE_OF
 * options must be there; else a message saying what is needed and what
 * is missing. */
static int check_needs(const ic_cli_command *cmd, const char *file, const ic_cli_value *values)
{
    char needs[512], missing[256] = "";
    size_t used = (size_t)snprintf(needs, sizeof needs, "%s", ic_cli_file_arg(cmd));
    if (!file)
        snprintf(missing, sizeof missing, "%s", ic_cli_file_arg(cmd));
    for (int k = 0; k < cmd->noptions; k++) {
        const ic_cli_option *opt = &cmd->options[k];
        if (opt->need != IC_OPT_REQUIRED || used >= sizeof needs)
            continue;
        used += (size_t)snprintf(needs + used, sizeof needs - used, " and %s %s", opt->name,
                                 opt->metavar);
        if (!values[k].given && !missing[0])
            snprintf(missing, sizeof missing, "%s", opt->name);
    }
    char one_of[256];
    int given_one = 0;
    if (one_of_text(one_of, sizeof one_of, cmd) > 0) {
        for (int k = 0; k < cmd->noptions; k++)
            given_one += cmd->options[k].need == IC_OPT_ONE_OF && values[k].given;
        if (given_one > 1) {
            fprintf(stderr, "intercurve %s: give only %s\n", cmd->name, one_of);
            return input_error(cmd);
        }
        if (used < sizeof needs)
            snprintf(needs + used, sizeof needs - used, " and %s", one_of);
        if (given_one == 0 && !missing[0])
            snprintf(missing, sizeof missing, "%s", one_of);
    }
    if (!missing[0])
        return 0;
    fprintf(stderr, "intercurve %s: needs %s (missing: %s)\n", cmd->name, needs, missing);
    return input_error(cmd);
}

int ic_cli_parse(const ic_cli_command *cmd, int argc, char **argv, const char **file,
                 ic_cli_value *values)
{
    *file = NULL;
    memset(values, 0, (size_t)cmd->noptions * sizeof *values);
    if (wants_help(argc, argv)) {
        ic_cli_print_help(cmd, stdout);
        return IC_CLI_HELP;
    }
    int only_files = 0; /* after `--` */
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        if (!only_files && strcmp(arg, "--") == 0) {
            only_files = 1;
        } else if (!only_files && arg[0] == '-' && arg[1] != '\0') {
            const int rc = read_option(cmd, argc, argv, &i, values);
            if (rc != 0)
                return rc;
        } else if (!*file) {
            *file = arg; /* "-": standard input */
        } else {
            fprintf(stderr, "intercurve %s: unexpected argument '%s' (the %s file is '%s')\n",
                    cmd->name, arg, cmd->file ? "CAD" : "problem", *file);
            return input_error(cmd);
        }
    }
    const int rc = fill_defaults(cmd, values);
    return rc != 0 ? rc : check_needs(cmd, *file, values);
}
