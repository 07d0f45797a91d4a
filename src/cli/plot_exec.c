/* `intercurve plot` runs intercurve-plot, the only program linked with
 * cairo: every other command starts without loading cairo and the two dozen
 * libraries it needs (docs/performance.md, "The command"). */
#include "cli/cli.h"

#include <errno.h>
#include <unistd.h>

/* where make install puts the helper, relative to the command's directory */
#ifndef IC_PLOT_HELPER_DIR
#define IC_PLOT_HELPER_DIR "../libexec/intercurve"
#endif
#define PLOT_HELPER "intercurve-plot"
/* bytes of a path this command handles */
#define PATH_BYTES 4096

/* The directory of this program into dir: from /proc/self/exe, else from
 * argv0 where it names one; 0 where neither tells. */
static int own_directory(char dir[PATH_BYTES], const char *argv0)
{
    ssize_t n = readlink("/proc/self/exe", dir, PATH_BYTES - 1);
    if (n <= 0) {
        if (!strchr(argv0, '/') || strlen(argv0) >= PATH_BYTES)
            return 0;
        n = (ssize_t)strlen(argv0);
        memcpy(dir, argv0, (size_t)n);
    }
    dir[n] = '\0';
    char *slash = strrchr(dir, '/');
    if (!slash)
        return 0;
    *slash = '\0';
    return 1;
}

int ic_cli_exec_plot(char **argv)
{
    char dir[PATH_BYTES], path[2 * PATH_BYTES];
    if (!own_directory(dir, argv[0])) {
        fprintf(stderr, "intercurve plot: cannot find the directory of this program, where "
                        "%s is\n", PLOT_HELPER);
        return EXIT_COMPUTE;
    }
    /* beside the command (the build tree), then where make install puts it */
    static const char *const places[] = {"", "/" IC_PLOT_HELPER_DIR};
    int err = ENOENT;
    for (size_t i = 0; i < sizeof places / sizeof places[0]; i++) {
        snprintf(path, sizeof path, "%s%s/%s", dir, places[i], PLOT_HELPER);
        if (access(path, X_OK) == 0) {
            execv(path, argv); /* returns only when it failed */
            err = errno;
            break;
        }
    }
    fprintf(stderr, "intercurve plot: cannot run %s (%s; looked in %s and %s/%s)\n", PLOT_HELPER,
            strerror(err), dir, dir, IC_PLOT_HELPER_DIR);
    return EXIT_COMPUTE;
}
