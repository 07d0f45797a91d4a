/* The exact paths' door (exact.h): each closed form tried in turn. */
#include "exact_paths.h"

ic_status ic_trace_exact(ic_trace_result *r, ic_pair *pair, const ic_trace_options *user_opt,
                         int *done, ic_error *err)
{
    *done = 0;
    ic_status st = ic_trace_exact_revolution(r, pair, user_opt, done, err);
    if (st == IC_OK && !*done)
        st = ic_trace_exact_conic(r, pair, user_opt, done, err);
    return st;
}
