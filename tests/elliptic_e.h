/* The complete elliptic integral of the second kind for the tests of
 * ellipses' lengths (test_exact_conics.c checks it against mpmath;
 * test_nurbs_conics.c): E(m) by the arithmetic-geometric mean (Abramowitz
 * and Stegun (1964), 17.6.3-4): E = K (1 - sum 2^(n-1) c_n^2), K = pi /
 * (2 a_N), c_0^2 = m. An ellipse of semi-axes a >= b is 4 a E(1 - b^2 /
 * a^2) long. */
#ifndef IC_TEST_ELLIPTIC_E_H
#define IC_TEST_ELLIPTIC_E_H

#include <float.h>
#include <math.h>

static inline double ellipe(double m)
{
    double a = 1, b = sqrt(1 - m), sum = 0.5 * m, w = 0.5;
    for (int n = 0; n < 40 && fabs(a - b) > DBL_EPSILON * a; n++) {
        const double c = 0.5 * (a - b), an = 0.5 * (a + b);
        b = sqrt(a * b), a = an, w *= 2;
        sum += w * c * c;
    }
    return 3.14159265358979323846 / (2 * a) * (1 - sum);
}

#endif
