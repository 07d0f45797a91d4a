/*
 * The threads of one trace (workers.h). A batch is handed out one job at a
 * time under the pool's lock: the jobs are coarse (a subtree of the search,
 * a cell's refinement), so the lock costs nothing next to them.
 */
#include "workers.h"
#include "local/pair_access.h"
#include "surface/surface_copy.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct {
    pthread_t thread;
    ic_pair *pair;
    ic_surface *own[2]; /* the pair's surfaces (own[1] NULL when shared) */
    struct ic_trace_workers *pool;
} worker;

struct ic_trace_workers {
    pthread_mutex_t lock;
    pthread_cond_t wake; /* a batch or the end is posted */
    pthread_cond_t idle; /* the last worker left a batch */
    worker *w;
    int nthreads; /* started */
    /* the batch under way */
    ic_trace_job *job;
    void *ctx;
    int n, next;
    int busy;        /* workers not yet done with this batch */
    long generation; /* counts the batches posted */
    int quit;
};

int ic_trace_thread_count(int threads)
{
    if (threads <= 0) {
        const long cores = sysconf(_SC_NPROCESSORS_ONLN);
        threads = cores > 0 ? (int)(cores < IC_TRACE_MAX_THREADS ? cores : IC_TRACE_MAX_THREADS)
                            : 1;
    }
    return threads < IC_TRACE_MAX_THREADS ? threads : IC_TRACE_MAX_THREADS;
}

/* Takes the batch's jobs one by one until none is left (the lock held on
 * entry and on return). */
static void take_jobs(ic_trace_workers *p, ic_pair *pair)
{
    while (p->next < p->n) {
        const int i = p->next++;
        pthread_mutex_unlock(&p->lock);
        p->job(p->ctx, i, pair);
        pthread_mutex_lock(&p->lock);
    }
}

static void *work(void *arg)
{
    worker *me = arg;
    ic_trace_workers *p = me->pool;
    long seen = 0;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (!p->quit && p->generation == seen)
            pthread_cond_wait(&p->wake, &p->lock);
        if (p->quit)
            break;
        seen = p->generation;
        take_jobs(p, me->pair);
        if (--p->busy == 0)
            pthread_cond_signal(&p->idle);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

static void free_copy(worker *w)
{
    ic_pair_free(w->pair);
    ic_surface_free(w->own[0]);
    ic_surface_free(w->own[1]);
}

/* The worker's own pair: copies of the surfaces, shared as in the
 * original (a self-intersection's one surface, or one surface given twice). */
static ic_status copy_pair(worker *w, ic_pair *pair, ic_error *err)
{
    ic_surface *A = ic_pair_surface(pair, 0), *B = ic_pair_surface(pair, 1);
    ic_status st = ic_surface_copy(&w->own[0], A, err);
    if (st == IC_OK && B != A)
        st = ic_surface_copy(&w->own[1], B, err);
    if (st == IC_OK)
        st = ic_pair_new(&w->pair, w->own[0],
                         ic_pair_is_self(pair) ? NULL : B != A ? w->own[1] : w->own[0], err);
    if (st == IC_OK)
        ic_pair_set_frame(w->pair, &ic_pair_pairing(pair)->frame);
    if (st != IC_OK)
        free_copy(w);
    return st;
}

/* Frees what new made: the copies of the first `copies` workers, the
 * arrays, and the lock when `locked`. */
static void release(ic_trace_workers *p, int copies, int locked)
{
    for (int k = 0; k < copies; k++)
        free_copy(&p->w[k]);
    if (locked) {
        pthread_mutex_destroy(&p->lock);
        pthread_cond_destroy(&p->wake);
        pthread_cond_destroy(&p->idle);
    }
    free(p->w);
    free(p);
}

ic_status ic_trace_workers_new(ic_trace_workers **out, ic_pair *pair, int n, ic_error *err)
{
    *out = NULL;
    if (n <= 1)
        return IC_OK;
    ic_trace_workers *p = calloc(1, sizeof *p);
    if (!p || !(p->w = calloc((size_t)(n - 1), sizeof *p->w))) {
        free(p);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory starting threads");
    }
    ic_status st = IC_OK;
    int copies = 0;
    while (copies < n - 1 && (st = copy_pair(&p->w[copies], pair, err)) == IC_OK)
        copies++;
    if (st != IC_OK) { /* out of memory, or a callback surface: one thread */
        release(p, copies, 0);
        return st == IC_ERR_NOMEM ? st : IC_OK;
    }
    if (pthread_mutex_init(&p->lock, NULL) != 0) {
        release(p, copies, 0);
        return IC_OK;
    }
    pthread_cond_init(&p->wake, NULL);
    pthread_cond_init(&p->idle, NULL);
    for (int k = 0; k < copies; k++) {
        p->w[k].pool = p;
        if (pthread_create(&p->w[k].thread, NULL, work, &p->w[k]) != 0)
            break; /* as many threads as the system gives */
        p->nthreads++;
    }
    for (int k = p->nthreads; k < copies; k++)
        free_copy(&p->w[k]);
    if (p->nthreads == 0) {
        release(p, 0, 1);
        return IC_OK;
    }
    *out = p;
    return IC_OK;
}

void ic_trace_workers_free(ic_trace_workers *p)
{
    if (!p)
        return;
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    for (int k = 0; k < p->nthreads; k++)
        pthread_join(p->w[k].thread, NULL);
    release(p, p->nthreads, 1);
}

int ic_trace_workers_count(const ic_trace_workers *p) { return p ? p->nthreads + 1 : 1; }

void ic_trace_workers_run(ic_trace_workers *p, ic_pair *pair, ic_trace_job *job, void *ctx,
                          int n)
{
    if (!p) {
        for (int i = 0; i < n; i++)
            job(ctx, i, pair);
        return;
    }
    pthread_mutex_lock(&p->lock);
    p->job = job;
    p->ctx = ctx;
    p->n = n;
    p->next = 0;
    p->busy = p->nthreads;
    p->generation++;
    pthread_cond_broadcast(&p->wake);
    take_jobs(p, pair);
    while (p->busy > 0)
        pthread_cond_wait(&p->idle, &p->lock);
    /* out of memory noted in a copy is the trace's (ic_trace asks the pair) */
    for (int k = 0; k < p->nthreads; k++)
        ic_pair_nomem_take(pair, p->w[k].pair);
    pthread_mutex_unlock(&p->lock);
}
