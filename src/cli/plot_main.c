/* intercurve-plot: the drawing half of the command, which `intercurve plot`
 * runs with its own arguments (plot_exec.c); the one program linked with
 * cairo. */
#include "cli/cli.h"

int main(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "plot") != 0) {
        fputs("intercurve-plot draws for 'intercurve plot' (try 'intercurve plot --help')\n",
              stderr);
        return EXIT_INPUT;
    }
    return ic_cmd_plot(argc - 1, argv + 1);
}
