/* Lengths of the test curves by composite Simpson in long double, from their
 * closed-form speed (independent of the tracer). 20000 panels: the error is
 * below 1e-15 relative for these smooth integrands. */
#ifndef IC_TEST_CURVE_LENGTHS_H
#define IC_TEST_CURVE_LENGTHS_H

#include <math.h>

/* The lobe of Viviani's curve: the integral of sqrt(1 + cos^2(t/2)) over
 * [0, 2 pi] by composite Simpson in long double (independent of the tracer). */
static inline double viviani_lobe(void)
{
    const int n = 20000;
    const long double h = 2 * 3.14159265358979323846264338327950288L / n;
    long double sum = 0;
    for (int i = 0; i <= n; i++) {
        const long double c = cosl(i * h / 2);
        const long double f = sqrtl(1 + c * c);
        sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * f;
    }
    return (double)(sum * h / 3);
}

/* Length of the Enneper double curve (4w + 8w^3/3, 0, -3 - 2w^2) between w0 and
 * w1: |c'(w)| = sqrt((4 + 8w^2)^2 + 16w^2), Simpson in long double. */
static inline double enneper_arc(double w0, double w1)
{
    const int n = 20000;
    const long double h = ((long double)w1 - w0) / n;
    long double sum = 0;
    for (int i = 0; i <= n; i++) {
        const long double w = w0 + i * h, a = 4 + 8 * w * w;
        sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * sqrtl(a * a + 16 * w * w);
    }
    return (double)fabsl(sum * h / 3);
}

/* Composite Simpson of a speed |c'(t)| over [a, b] in long double, 20000 panels. */
static inline double simpson_length(long double (*speed)(long double), long double a, long double b)
{
    const int n = 20000;
    const long double h = (b - a) / n;
    long double sum = 0;
    for (int i = 0; i <= n; i++)
        sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * speed(a + i * h);
    return (double)(sum * h / 3);
}

#endif
