/*
** curvefig: curve algorithms (Bernstein and B-spline bases, Bézier,
** rational Bézier, B-spline and NURBS curves in R^N) for course figures.
** This umbrella header includes every public header of the core library.
*/
#ifndef CURVEFIG_H
#define CURVEFIG_H

#include "curvefig/version.h"
#include "curvefig/core.h"
#include "curvefig/bezier.h"
#include "curvefig/bernstein.h"
#include "curvefig/geometry.h"
#include "curvefig/conic.h"
#include "curvefig/offset.h"
#include "curvefig/knots.h"
#include "curvefig/bspline.h"
#include "curvefig/interp.h"
#include "curvefig/surface.h"
#include "curvefig/surface-make.h"
#include "curvefig/surface-triangle.h"
#include "curvefig/view.h"
#include "curvefig/visibility.h"
#include "curvefig/reduce.h"

#endif
