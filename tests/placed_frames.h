/* Placed primitives written as formulas, for the tests of placed primitives
 * (test_placed, test_placed_trace): a frame derived by hand and the formula
 * twin of a primitive placed in it, x = c + sum_j L_j e_j and
 * L_j = e_j . (x - c), built as text from the frame's numbers. */
#ifndef IC_TEST_PLACED_FRAMES_H
#define IC_TEST_PLACED_FRAMES_H

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct {
    double c[3];    /* center */
    double e[3][3]; /* rows e1, e2, e3 */
} placed_frame;

/* Axis (1, 2, 2) with ref_direction (1, 0, 0), by hand: e3 = (1, 2, 2)/3;
 * the ref less its part along e3, (1, 0, 0) - (1/3) e3 = (8, -2, -2)/9, of
 * length 2 sqrt(2)/3, gives e1 = (4, -1, -1)/(3 sqrt 2); e2 = e3 x e1 =
 * (0, 9, -9)/(9 sqrt 2) = (0, 1, -1)/sqrt 2. (e1 x e2 = (2, 4, 4)/6 = e3:
 * right-handed.) The same e1 is the default for this axis: x is the
 * coordinate axis least aligned with it. */
static inline void tilted_frame(placed_frame *f, const double c[3])
{
    const double r2 = sqrt(2.0);
    const double e[3][3] = {{4 / (3 * r2), -1 / (3 * r2), -1 / (3 * r2)},
                            {0, 1 / r2, -1 / r2},
                            {1.0 / 3, 2.0 / 3, 2.0 / 3}};
    memcpy(f->e, e, sizeof e);
    memcpy(f->c, c, sizeof f->c);
}

/* Axis x with ref_direction z: e3 = x, e1 = z, e2 = e3 x e1 = x x z = -y. */
static inline void along_x_frame(placed_frame *f, const double c[3])
{
    const double e[3][3] = {{0, 0, 1}, {0, -1, 0}, {1, 0, 0}};
    memcpy(f->e, e, sizeof e);
    memcpy(f->c, c, sizeof f->c);
}

/* The space formulas x, y, z of a surface given by its local formulas
 * local[j] (in u, v): x_k = c_k + sum_j e_j[k] local_j. */
static inline void twin_parametric(char out[3][512], const placed_frame *f,
                                   const char *const local[3])
{
    for (int k = 0; k < 3; k++)
        snprintf(out[k], 512, "(%.17g) + (%.17g)*(%s) + (%.17g)*(%s) + (%.17g)*(%s)", f->c[k],
                 f->e[0][k], local[0], f->e[1][k], local[1], f->e[2][k], local[2]);
}

/* f_local's template with X, Y, Z standing for the local coordinates,
 * each replaced by e_j . (x - c). 0, or -1 when out (size bytes) is short. */
static inline int twin_implicit(char *out, size_t size, const placed_frame *f, const char *tmpl)
{
    char L[3][200];
    for (int j = 0; j < 3; j++)
        snprintf(L[j], sizeof L[j],
                 "((%.17g)*(x - (%.17g)) + (%.17g)*(y - (%.17g)) + (%.17g)*(z - (%.17g)))",
                 f->e[j][0], f->c[0], f->e[j][1], f->c[1], f->e[j][2], f->c[2]);
    size_t n = 0;
    for (const char *p = tmpl; *p; p++) {
        const char *piece = *p == 'X' ? L[0] : *p == 'Y' ? L[1] : *p == 'Z' ? L[2] : NULL;
        const size_t len = piece ? strlen(piece) : 1;
        if (n + len + 1 > size)
            return -1;
        memcpy(out + n, piece ? piece : p, len);
        n += len;
    }
    out[n] = '\0';
    return 0;
}

#endif
