/* The truth file of arc-length derivatives (tests/truth/transversal_truth.txt,
 * made by gen_transversal_truth.py): one case per point of a known curve. */
#ifndef IC_TRUTH_FILE_H
#define IC_TRUTH_FILE_H

#include <stdio.h>
#include <string.h>

typedef struct {
    double point[3];
    double d[8][3];
    double kappa, tau, kappa_p, tau_p;
    char name[32], extra[96];
} truth_case;

static inline int read_truth(const char *path, truth_case *cases, int max)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[2048];
    int n = -1;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "case ", 5) == 0 && n + 1 < max) {
            n++;
            memset(&cases[n], 0, sizeof cases[n]);
            sscanf(line + 5, "%31s %95[^\n]", cases[n].name, cases[n].extra);
        } else if (n >= 0 && strncmp(line, "point ", 6) == 0) {
            sscanf(line + 6, "%lf %lf %lf", &cases[n].point[0], &cases[n].point[1],
                   &cases[n].point[2]);
        } else if (n >= 0 && line[0] == 'd' && line[1] >= '1' && line[1] <= '8') {
            const int k = line[1] - '1';
            sscanf(line + 3, "%lf %lf %lf", &cases[n].d[k][0], &cases[n].d[k][1],
                   &cases[n].d[k][2]);
        } else if (n >= 0 && strncmp(line, "frenet ", 7) == 0) {
            sscanf(line + 7, "%lf %lf %lf %lf", &cases[n].kappa, &cases[n].tau,
                   &cases[n].kappa_p, &cases[n].tau_p);
        }
    }
    fclose(f);
    return n + 1;
}

#endif
