/* Mathematical constants (C11 <math.h> has no M_PI without extensions). */
#ifndef IC_MATHCONST_H
#define IC_MATHCONST_H
#define IC_PI 3.14159265358979323846264338327950288
#define IC_E 2.71828182845904523536028747135266250
#endif
