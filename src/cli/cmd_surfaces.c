/* intercurve surfaces: every surface of a STEP or IGES file, so that a
 * problem file can name two of them (docs/cad-files.md). */
#include "cli/cli.h"
#include "api/api.h"

enum { OPT_FORMAT, NOPTIONS };

static const ic_cli_option SURFACES_OPTIONS[NOPTIONS] = {
    [OPT_FORMAT] = {.name = "--format",
                    .metavar = "FMT",
                    .kind = IC_OPT_CHOICE,
                    .choices = "text|json",
                    .fallback = "text",
                    .help = "text: one line per surface; json: one document"},
};

static const ic_cli_command SURFACES = {
    .name = "surfaces",
    .file = "FILE.step|FILE.igs",
    .summary = "Lists every surface of a STEP (.step, .stp) or IGES (.igs, .iges) file: its\n"
               "entity (STEP instance #N, IGES directory entry DE N), type, name, parameter\n"
               "range and the file's length unit, and for each surface that is not read, why.\n"
               "A problem file names a surface by its entity: {\"type\": \"step\", \"file\": ...,\n"
               "\"entity\": N} (docs/problem-files.md).",
    .options = SURFACES_OPTIONS,
    .noptions = NOPTIONS,
    .notes = "example:\n"
             "  intercurve surfaces tests/data/cad/primitives.step\n",
};

int ic_cmd_surfaces(int argc, char **argv)
{
    const char *file;
    ic_cli_value v[NOPTIONS];
    int rc = ic_cli_parse(&SURFACES, argc, argv, &file, v);
    if (rc != 0)
        return rc == IC_CLI_HELP ? 0 : rc;
    ic_error err;
    ic_error_clear(&err);
    int read_failed;
    const ic_status st =
        ic_api_list_surfaces(stdout, file, v[OPT_FORMAT].choice == 1, &read_failed, &err);
    if (st != IC_OK && read_failed) {
        ic_cli_print_error(NULL, &err); /* the message begins with the file */
        return st == IC_ERR_NOMEM ? EXIT_COMPUTE : EXIT_INPUT;
    }
    if (st == IC_OK && fflush(stdout) == 0)
        return 0;
    fprintf(stderr, "intercurve: cannot write the output (%s)\n",
            st == IC_OK ? "a write error" : err.message);
    return EXIT_COMPUTE;
}
