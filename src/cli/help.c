/* Every command's --help, written from its option table (options.h). */
#include "cli/options.h"

#include <math.h>
#include <string.h>

/* Width of the usage lines before they wrap. */
enum { USAGE_WIDTH = 90 };

/* "[--order K]", "-o FIGURE", "[--no-chart]" into out. */
static void synopsis_item(char *out, size_t size, const ic_cli_option *opt)
{
    const char *open = opt->need == IC_OPT_REQUIRED ? "" : "[";
    const char *close = opt->need == IC_OPT_REQUIRED ? "" : "]";
    if (opt->metavar)
        snprintf(out, size, "%s%s %s%s", open, opt->name, opt->metavar, close);
    else
        snprintf(out, size, "%s%s%s", open, opt->name, close);
}

/* "(--at X,Y,Z | --params U,V[,P,Q])" into out: the IC_OPT_ONE_OF options. */
static void synopsis_one_of(char *out, size_t size, const ic_cli_command *cmd)
{
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < cmd->noptions && used < size; k++)
        if (cmd->options[k].need == IC_OPT_ONE_OF)
            used += (size_t)snprintf(out + used, size - used, "%s%s %s", used ? " | " : "(",
                                     cmd->options[k].name, cmd->options[k].metavar);
    if (used && used + 1 < size)
        strcat(out, ")");
}

/* Prints one item of the usage, wrapping before it would pass USAGE_WIDTH. */
static void usage_word(FILE *f, const char *word, int *column, int indent)
{
    if (*column + 1 + (int)strlen(word) > USAGE_WIDTH) {
        fprintf(f, "\n%*s", indent, "");
        *column = indent;
    } else {
        fputc(' ', f);
        (*column)++;
    }
    fputs(word, f);
    *column += (int)strlen(word);
}

static void print_usage(const ic_cli_command *cmd, FILE *f)
{
    int column = fprintf(f, "usage: intercurve %s %s", cmd->name, ic_cli_file_arg(cmd));
    const int indent = (int)strlen("usage: intercurve ") + (int)strlen(cmd->name) + 1;
    char item[256];
    int one_of_done = 0;
    for (int k = 0; k < cmd->noptions; k++) {
        const ic_cli_option *opt = &cmd->options[k];
        if (opt->need == IC_OPT_ONE_OF) {
            if (one_of_done++)
                continue;
            synopsis_one_of(item, sizeof item, cmd);
        } else {
            synopsis_item(item, sizeof item, opt);
        }
        usage_word(f, item, &column, indent);
    }
    fputc('\n', f);
}

/* The range and default of an option, "K in 1..16; default 4", or "";
 * the default goes on a line of its own where the line would be longer
 * than USAGE_WIDTH from `column`. */
static void range_line(char *out, size_t size, const ic_cli_option *opt, int column)
{
    char lo[32], hi[32], list[256];
    ic_cli_format_bound(lo, sizeof lo, opt->lo);
    ic_cli_format_bound(hi, sizeof hi, opt->hi);
    out[0] = '\0';
    if (opt->kind == IC_OPT_INT)
        snprintf(out, size, "%s in %s..%s", opt->metavar, lo, hi);
    else if (opt->kind == IC_OPT_REAL && isinf(opt->hi))
        snprintf(out, size, "%s > %s", opt->metavar, lo);
    else if (opt->kind == IC_OPT_REAL)
        snprintf(out, size, "%s in (%s, %s]", opt->metavar, lo, hi);
    else if (opt->kind == IC_OPT_SIZE) {
        char lo2[32];
        ic_cli_format_bound(lo2, sizeof lo2, opt->lo2);
        snprintf(out, size, "W in %s..%s, H in %s..%s", lo, hi, lo2, hi);
    } else if (opt->kind == IC_OPT_CHOICE) {
        ic_cli_choices_text(list, sizeof list, opt->choices);
        snprintf(out, size, "one of %s", list);
    }
    if (opt->fallback) {
        const size_t used = strlen(out);
        const int wraps = column + (int)(used + strlen(opt->fallback)) + 10 > USAGE_WIDTH;
        snprintf(out + used, size - used, "%s%*sdefault %s",
                 !used   ? ""
                 : wraps ? "\n"
                         : "; ",
                 used && wraps ? column : 0, "", opt->fallback);
    }
}

/* The option's help lines, then its range line, in the help column. */
static void print_option(FILE *f, const ic_cli_option *opt, int column)
{
    char label[128], range[512];
    if (opt->metavar)
        snprintf(label, sizeof label, "%s %s", opt->name, opt->metavar);
    else
        snprintf(label, sizeof label, "%s", opt->name);
    fprintf(f, "  %-*s", column - 2, label);
    const char *line = opt->help;
    for (int first = 1; *line; first = 0) {
        const size_t len = strcspn(line, "\n");
        fprintf(f, "%*s%.*s\n", first ? 0 : column, "", (int)len, line);
        line += len + (line[len] == '\n');
    }
    range_line(range, sizeof range, opt, column);
    if (range[0])
        fprintf(f, "%*s%s\n", column, "", range);
}

const char *ic_cli_file_arg(const ic_cli_command *cmd)
{
    return cmd->file ? cmd->file : "PROBLEM.json";
}

void ic_cli_print_help(const ic_cli_command *cmd, FILE *f)
{
    print_usage(cmd, f);
    fprintf(f, "\n%s\n\noptions:\n", cmd->summary);
    int width = (int)strlen("-h, --help");
    for (int k = 0; k < cmd->noptions; k++) {
        const ic_cli_option *opt = &cmd->options[k];
        const int w = (int)strlen(opt->name) + (opt->metavar ? 1 + (int)strlen(opt->metavar) : 0);
        if (w > width)
            width = w;
    }
    const int column = width + 4; /* two spaces before the label, two after */
    for (int k = 0; k < cmd->noptions; k++)
        print_option(f, &cmd->options[k], column);
    fprintf(f, "  %-*s%s\n", column - 2, "-h, --help", "print this help");
    if (cmd->file)
        fprintf(f, "\n%s is a STEP or IGES file (docs/cad-files.md).\n"
                   "A value follows its option as the next argument or after '=' (--format json or\n"
                   "--format=json); after -- every argument is taken as the file.\n",
                cmd->file);
    else
        fputs("\nPROBLEM.json is a problem file (docs/problem-files.md), or - for standard input.\n"
              "A value follows its option as the next argument or after '=' (--order 3 or\n"
              "--order=3); after -- every argument is taken as the problem file.\n",
              f);
    if (cmd->notes)
        fprintf(f, "\n%s", cmd->notes);
}
