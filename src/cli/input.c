/* The problem file of a command, and the library's errors as messages. */
#include "cli/cli.h"

#include <errno.h>

const char *ic_cli_file_name(const char *file) { return strcmp(file, "-") == 0 ? "<stdin>" : file; }

int ic_cli_load_problem(ic_problem **p, const char *file, unsigned flags)
{
    ic_error err;
    ic_error_clear(&err);
    ic_status st;
    if (strcmp(file, "-") == 0) {
        st = ic_problem_read(p, stdin, ic_cli_file_name(file), flags, &err);
    } else {
        FILE *f = fopen(file, "rb");
        if (!f) {
            *p = NULL;
            fprintf(stderr, "intercurve: %s: cannot open %s: %s\n", file, file, strerror(errno));
            return EXIT_INPUT;
        }
        st = ic_problem_read(p, f, file, flags, &err);
        fclose(f);
    }
    if (st == IC_OK)
        return 0;
    ic_cli_print_error(ic_cli_file_name(file), &err);
    return EXIT_INPUT;
}

void ic_cli_print_error(const char *file, const ic_error *err)
{
    fprintf(stderr, "intercurve: ");
    if (file)
        fprintf(stderr, "%s: ", file);
    if (err->path[0])
        fprintf(stderr, "%s: ", err->path);
    if (err->column > 0)
        fprintf(stderr, "column %d: ", err->column);
    fprintf(stderr, "%s", err->message);
    const size_t len = strlen(err->message);
    if (len == 0 || err->message[len - 1] != '\n')
        fputc('\n', stderr);
}
