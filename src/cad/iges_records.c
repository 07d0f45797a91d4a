/* IGES's fixed-column lines: data, then the section letter in column 73
 * and the sequence number in columns 74-80 (P: the DE pointer in 66-72). */
#include "cad/iges_records.h"

#include <string.h>

void ic_iges_records_start(iges_records *r, FILE *f, char section)
{
    r->f = f;
    r->section = section;
    r->width = section == 'P' ? 64 : 72;
    r->de = 0;
    r->seq = 0;
    r->used = 0;
}

void ic_iges_records_end_line(iges_records *r)
{
    if (r->used == 0)
        return;
    r->seq++;
    if (r->f) {
        if (r->section == 'P')
            fprintf(r->f, "%-64.*s %7d", r->used, r->line, r->de);
        else
            fprintf(r->f, "%-72.*s", r->used, r->line);
        fprintf(r->f, "%c%7d\n", r->section, r->seq);
    }
    r->used = 0;
}

void ic_iges_records_put(iges_records *r, const char *text)
{
    size_t n = strlen(text);
    if (n > (size_t)r->width)
        n = (size_t)r->width;
    if (r->used + (int)n > r->width)
        ic_iges_records_end_line(r);
    memcpy(r->line + r->used, text, n);
    r->used += (int)n;
}
