/* The length unit of an IGES file (iges_surface.h): the global section's
 * units flag (field 14) and, for flag 3, its units name (field 15). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "iges_surface.h"

typedef struct {
    int flag;
    const char *name;     /* what the description calls it */
    const char *spelling; /* the name IGES 5.3 gives for it in field 15 */
    double metres;
} iges_unit;

static const iges_unit UNITS[] = {
    {1, "inch", "IN", 0.0254},     {2, "mm", "MM", 1e-3},       {4, "ft", "FT", 0.3048},
    {5, "mile", "MI", 1609.344},   {6, "m", "M", 1},            {7, "km", "KM", 1e3},
    {8, "mil", "MIL", 2.54e-5},    {9, "um", "UM", 1e-6},       {10, "cm", "CM", 1e-2},
    {11, "uin", "UIN", 2.54e-8},
};

void ic_iges_length_unit(const ic_iges_file *f, char *unit, size_t size, double *metres)
{
    double flag = 0;
    char name[24];
    ic_iges_string(&f->global, 14, name, sizeof name);
    for (char *c = name; *c; c++)
        *c = (char)toupper((unsigned char)*c);
    if (strcmp(name, "INCH") == 0)
        strcpy(name, "IN");
    if (ic_iges_number(&f->global, 13, &flag) < 0)
        flag = 0;
    for (size_t k = 0; k < sizeof UNITS / sizeof UNITS[0]; k++)
        if (flag == UNITS[k].flag || (flag == 3 && strcmp(name, UNITS[k].spelling) == 0)) {
            snprintf(unit, size, "%s", UNITS[k].name);
            *metres = UNITS[k].metres;
            return;
        }
    /* flag 3 with a name not in the table: the name, size unknown */
    snprintf(unit, size, "%s", flag == 3 ? name : "");
    *metres = 0;
}
