/* The Markdown report: the machine, the net check, the table. */
#ifndef IC_PEERS_TABLE_H
#define IC_PEERS_TABLE_H

#include <stdio.h>

#include "metrics.h"

void table_header(FILE *f, unsigned time_limit);
void table_net_check(FILE *f, const bench_case *c, double devA, double devB);
void table_start(FILE *f);
void table_row(FILE *f, const bench_case *c, const char *engine, const peer_summary *s);

#endif
