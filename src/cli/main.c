/* The intercurve command: dispatch to the subcommands. */
#include "cli/cli.h"

#include <string.h>

static const char USAGE[] =
    "intercurve " IC_VERSION " - differential geometry of surface intersection curves\n"
    "\n"
    "usage: intercurve COMMAND PROBLEM.json [options]\n"
    "\n"
    "commands:\n"
    "  eval    point, normal, fundamental forms, principal curvatures and the\n"
    "          derivative tensor of one surface of a problem at a point\n"
    "  point   the intersection at a point: its type, the Frenet apparatus and the\n"
    "          derivatives of any order with respect to arc length\n"
    "  trace   trace the whole intersection: every curve with its Frenet apparatus,\n"
    "          its shape and the tangential points met\n"
    "  plot    draw the surfaces, the curves coloured by curvature, Frenet frames,\n"
    "          singular points, and a chart of curvature and torsion (SVG, PNG, PDF)\n"
    "  surfaces\n"
    "          list the surfaces of a STEP or IGES file (intercurve surfaces\n"
    "          FILE.step|FILE.igs), so that a problem file can name them\n"
    "  verify  check a saved trace against its problem without the tracer (intercurve\n"
    "          verify PROBLEM.json --trace TRACE.json): proven or not, and why\n"
    "\n"
    "example:\n"
    "  intercurve eval examples/viviani.json --surface sphere --at 0.3,0.4\n"
    "  intercurve point examples/viviani.json --at 1.5,0.8660254037844386,1\n"
    "\n"
    "'intercurve COMMAND --help' describes a command and its options (docs/cli.md\n"
    "lists them all). PROBLEM.json may be - for standard input; an option's value\n"
    "follows it or an '=' (--order 3, --order=3). Exit status: 0 success,\n"
    "1 wrong input (the message says what and where), 2 the computation cannot be done.\n";

int main(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        fputs(USAGE, argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_INPUT : 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        puts("intercurve " IC_VERSION);
        return 0;
    }
    if (strcmp(argv[1], "eval") == 0)
        return ic_cmd_eval(argc - 1, argv + 1);
    if (strcmp(argv[1], "point") == 0)
        return ic_cmd_point(argc - 1, argv + 1);
    if (strcmp(argv[1], "trace") == 0)
        return ic_cmd_trace(argc - 1, argv + 1);
    if (strcmp(argv[1], "plot") == 0) /* the one command that draws: cairo only there */
        return ic_cli_exec_plot(argv);
    if (strcmp(argv[1], "surfaces") == 0)
        return ic_cmd_surfaces(argc - 1, argv + 1);
    if (strcmp(argv[1], "verify") == 0)
        return ic_cmd_verify(argc - 1, argv + 1);
    fprintf(stderr, "intercurve: unknown command '%s' (try 'intercurve --help')\n", argv[1]);
    return EXIT_INPUT;
}
