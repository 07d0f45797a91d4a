/* A problem traced in one call (api.h): the pair, the trace and the fit,
 * the one copy of these steps that the command and the bindings share. */
#include "api/api.h"

#include <stddef.h>

ic_status ic_api_problem_pair(ic_pair **pair, const ic_problem *problem, ic_error *err)
{
    const int self = ic_problem_is_self(problem);
    return ic_pair_new(pair, ic_problem_surface(problem, 0),
                       self ? NULL : ic_problem_surface(problem, 1), err);
}

ic_status ic_api_trace_problem(ic_trace_result **res, ic_pair **pair, const ic_problem *problem,
                               ic_trace_options *opt, double fit_tol, ic_api_stage *failed,
                               ic_error *err)
{
    *res = NULL;
    opt->has_box = ic_problem_box(problem, opt->box);
    *failed = IC_API_PAIR;
    ic_status st = ic_api_problem_pair(pair, problem, err);
    if (st == IC_OK) {
        *failed = IC_API_TRACE;
        st = ic_trace(res, *pair, opt, err);
    }
    if (st == IC_OK && fit_tol > 0) {
        *failed = IC_API_FIT;
        st = ic_trace_fit(*res, *pair, fit_tol, err);
    }
    if (st != IC_OK) {
        ic_trace_result_free(*res);
        ic_pair_free(*pair);
        *res = NULL;
        *pair = NULL;
    }
    return st;
}
