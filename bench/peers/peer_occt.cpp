// OpenCASCADE on a case: GeomInt_IntSS (the engine behind GeomAPI_IntSS,
// which also gives the isolated points) on the two nets as
// Geom_BSplineSurface and, separately, on the analytic surfaces
// (Geom_SphericalSurface, Geom_CylindricalSurface, Geom_Plane,
// Geom_ToroidalSurface) in the same placement. The curves it returns are
// differentiated with D3 for curvature and torsion.
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomInt_IntSS.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Ax3.hxx>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "peers.h"

namespace {

// the tolerance given to GeomInt_IntSS (length units): Precision::Confusion()
const double occt_tolerance = 1e-7;
// a surface that differs from our own evaluation of the net by more than this
// (length units) means the conversion is wrong
const double conversion_tolerance = 1e-12;
// parameter samples along each returned curve
const int samples_per_curve = 1000;

// A full knot vector as OpenCASCADE wants it: distinct values, multiplicities.
void split_knots(const double *full, int n, TColStd_Array1OfReal &knots,
                 TColStd_Array1OfInteger &mults, int &distinct)
{
    std::vector<double> values;
    std::vector<int> counts;
    for (int i = 0; i < n; i++) {
        if (!values.empty() && full[i] == values.back())
            counts.back()++;
        else
            values.push_back(full[i]), counts.push_back(1);
    }
    distinct = static_cast<int>(values.size());
    knots.Resize(1, distinct, Standard_False);
    mults.Resize(1, distinct, Standard_False);
    for (int i = 0; i < distinct; i++)
        knots(i + 1) = values[i], mults(i + 1) = counts[i];
}

Handle(Geom_Surface) bspline(const case_net &net)
{
    const int n1 = net.count[0], n2 = net.count[1];
    TColgp_Array2OfPnt poles(1, n1, 1, n2);
    TColStd_Array2OfReal weights(1, n1, 1, n2);
    for (int i = 0; i < n1; i++)
        for (int j = 0; j < n2; j++) {
            const double *p = net.points + 3 * (i * n2 + j);
            poles(i + 1, j + 1) = gp_Pnt(p[0], p[1], p[2]);
            weights(i + 1, j + 1) = net.weights[i * n2 + j];
        }
    TColStd_Array1OfReal uknots(1, 1), vknots(1, 1);
    TColStd_Array1OfInteger umults(1, 1), vmults(1, 1);
    int nu = 0, nv = 0;
    split_knots(net.knots[0], n1 + net.degree[0] + 1, uknots, umults, nu);
    split_knots(net.knots[1], n2 + net.degree[1] + 1, vknots, vmults, nv);
    return new Geom_BSplineSurface(poles, weights, uknots, vknots, umults, vmults, net.degree[0],
                                   net.degree[1]);
}

Handle(Geom_Surface) analytic(const exact_surface &s)
{
    const gp_Ax3 frame(gp_Pnt(s.center[0], s.center[1], s.center[2]),
                       gp_Dir(s.axis[0], s.axis[1], s.axis[2]),
                       gp_Dir(s.ref[0], s.ref[1], s.ref[2]));
    switch (s.kind) {
    case EXACT_PLANE:
        return new Geom_Plane(frame);
    case EXACT_SPHERE:
        return new Geom_SphericalSurface(frame, s.radius);
    case EXACT_CYLINDER:
        return new Geom_CylindricalSurface(frame, s.radius);
    case EXACT_TORUS:
        return new Geom_ToroidalSurface(frame, s.major, s.radius);
    }
    return Handle(Geom_Surface)();
}

int sample_curve(const Handle(Geom_Curve) &cv, peer_output *out)
{
    const double t0 = cv->FirstParameter(), t1 = cv->LastParameter();
    if (Precision::IsInfinite(t0) || Precision::IsInfinite(t1)) {
        peer_output_note(out, "an unbounded curve; ");
        return 0;
    }
    const double length = GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(cv));
    out->length += length;
    for (int i = 0; i <= samples_per_curve; i++) {
        gp_Pnt p;
        gp_Vec d1, d2, d3;
        cv->D3(t0 + (t1 - t0) * i / samples_per_curve, p, d1, d2, d3);
        const double xyz[3] = {p.X(), p.Y(), p.Z()};
        const double d[3][3] = {{d1.X(), d1.Y(), d1.Z()}, {d2.X(), d2.Y(), d2.Z()},
                                {d3.X(), d3.Y(), d3.Z()}};
        if (peer_output_add_derivs(out, xyz, d, length / (t1 - t0)) != 0)
            return -1;
    }
    return 0;
}

int collect(const GeomInt_IntSS &inter, peer_output *out)
{
    out->ncurves = inter.NbLines();
    std::map<std::string, int> kinds; // curve types returned, for the note
    for (int i = 1; i <= inter.NbLines(); i++) {
        const Handle(Geom_Curve) &cv = inter.Line(i);
        kinds[cv->DynamicType()->Name()]++;
        if (sample_curve(cv, out) != 0)
            return -1;
    }
    for (const auto &kind : kinds)
        peer_output_note(out, "%d %s; ", kind.second, kind.first.c_str());
    out->npoints = inter.NbPoints();
    for (int i = 1; i <= inter.NbPoints() && i <= PEER_MAX_POINTS; i++) {
        const gp_Pnt p = inter.Point(i);
        out->points[i - 1][0] = p.X(), out->points[i - 1][1] = p.Y(), out->points[i - 1][2] = p.Z();
    }
    return 0;
}

int run(const Handle(Geom_Surface) &a, const Handle(Geom_Surface) &b, peer_output *out,
        double *seconds)
{
    const auto t0 = std::chrono::steady_clock::now();
    try {
        GeomInt_IntSS inter(a, b, occt_tolerance);
        *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!inter.IsDone()) {
            out->failed = 1;
            peer_output_note(out, "IsDone() = false");
            return 0;
        }
        return collect(inter, out);
    } catch (const Standard_Failure &e) {
        *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        out->failed = 1;
        peer_output_note(out, "exception %s: %s", e.DynamicType()->Name(), e.GetMessageString());
        return 0;
    }
}

// Largest difference between OpenCASCADE's surface and our evaluation of the net.
double conversion_error(const Handle(Geom_Surface) &s, const case_net &net)
{
    double worst = 0.0;
    for (int a = 0; a <= 4; a++)
        for (int b = 0; b <= 4; b++) {
            double par[2], ours[3];
            for (int d = 0; d < 2; d++) {
                const double lo = net.knots[d][net.degree[d]], hi = net.knots[d][net.count[d]];
                par[d] = lo + (hi - lo) * (0.1 + 0.2 * (d ? b : a));
            }
            const gp_Pnt theirs = s->Value(par[0], par[1]);
            net_eval(&net, par[0], par[1], ours);
            worst = std::max(worst, theirs.Distance(gp_Pnt(ours[0], ours[1], ours[2])));
        }
    return worst;
}

} // namespace

extern "C" int peer_occt_nurbs(const bench_case *c, peer_output *out, double *seconds)
{
    const Handle(Geom_Surface) a = bspline(c->netA), b = bspline(c->netB);
    const double conv = std::max(conversion_error(a, c->netA), conversion_error(b, c->netB));
    if (!(conv <= conversion_tolerance)) {
        peer_output_note(out, "the OCCT surfaces are not the nets (off by %.1e)", conv);
        return -1;
    }
    return run(a, b, out, seconds);
}

extern "C" int peer_occt_analytic(const bench_case *c, peer_output *out, double *seconds)
{
    return run(analytic(c->A), analytic(c->B), out, seconds);
}
