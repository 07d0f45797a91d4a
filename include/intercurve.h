/**
 * @file intercurve.h
 * intercurve: differential geometry of surface intersection curves.
 * Includes every public header (docs/architecture.md lists the layers); each
 * carries its own extern "C" guards, so C++ includes this one as it is.
 */
#ifndef INTERCURVE_H
#define INTERCURVE_H

#include "intercurve/common.h"
#include "intercurve/defaults.h"
#include "intercurve/jet.h"
#include "intercurve/expr.h"
#include "intercurve/surface.h"
#include "intercurve/bspline.h"
#include "intercurve/local.h"
#include "intercurve/trace.h"
#include "intercurve/problem.h"
#include "intercurve/writers.h"
#include "intercurve/plot.h"
#include "intercurve/bindings.h"

#define IC_VERSION "0.1.0"

#endif
