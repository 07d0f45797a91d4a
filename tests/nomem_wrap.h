/* Allocation failure injection for tests/test_nomem.c, which is linked with
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc: every call of malloc,
 * calloc or realloc made by an object linked into the test program (the
 * static library's objects included; not those of shared libraries such as
 * cJSON or cairo) comes to the wrappers below. While armed they count the
 * allocations and make the one numbered fail_at (from 1) return NULL, as an
 * exhausted heap would. The counter is the test program's own: the library
 * keeps no mutable global state. */
#ifndef IC_TEST_NOMEM_WRAP_H
#define IC_TEST_NOMEM_WRAP_H

#include <execinfo.h>
#include <stdatomic.h>
#include <stddef.h>

enum { NOMEM_STACK = 16 };

/* count and armed are atomic: a trace's threads allocate too (the
 * scenario "trace, threads") */
static struct {
    atomic_int armed;  /* count (and fail) only while a scenario runs */
    atomic_long count; /* allocations since nomem_arm */
    long fail_at; /* the allocation that fails; 0: none */
    long failed;  /* allocations failed since nomem_arm */
    /* the calls that led to the failed allocation, innermost first */
    void *stack[NOMEM_STACK];
    int depth;
} nomem;

/* the real allocator (the linker's names under --wrap) */
void *__real_malloc(size_t size);
void *__real_calloc(size_t n, size_t size);
void *__real_realloc(void *p, size_t size);
void *__wrap_malloc(size_t size);
void *__wrap_calloc(size_t n, size_t size);
void *__wrap_realloc(void *p, size_t size);

/* Starts counting from zero; fail_at = 0 fails nothing (a counting run). */
static void nomem_arm(long fail_at)
{
    nomem.count = 0;
    nomem.failed = 0;
    nomem.depth = 0;
    nomem.fail_at = fail_at;
    nomem.armed = 1;
}

static void nomem_disarm(void) { nomem.armed = 0; }

/* 1 when this allocation is the one to fail; its calls are kept. */
static int nomem_fails(void)
{
    if (!nomem.armed || atomic_fetch_add(&nomem.count, 1) + 1 != nomem.fail_at)
        return 0;
    nomem.failed++;
    nomem.armed = 0; /* backtrace may allocate on its first call */
    nomem.depth = backtrace(nomem.stack, NOMEM_STACK);
    nomem.armed = 1;
    return 1;
}

void *__wrap_malloc(size_t size)
{
    if (nomem_fails())
        return NULL;
    return __real_malloc(size);
}

void *__wrap_calloc(size_t n, size_t size)
{
    if (nomem_fails())
        return NULL;
    return __real_calloc(n, size);
}

/* A failed realloc leaves the block as it was, as the real one does. */
void *__wrap_realloc(void *p, size_t size)
{
    if (nomem_fails())
        return NULL;
    return __real_realloc(p, size);
}

#endif
