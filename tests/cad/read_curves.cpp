// Reads the STEP and IGES curves intercurve writes (intercurve trace
// --format step|iges) with OpenCASCADE's readers, an independent reader
// (docs/testing.md, "STEP and IGES curves read by OpenCASCADE"), and checks
// that every edge lands on the problem's two surfaces: at kSamples points
// per edge, the distance to each surface, from its closed form below.
// usage: read_curves CASE CURVES CLOSED TOL FILE
//   CASE: viviani (examples/viviani-implicit.json) or cylinders
//   (examples/cylinders.json); CURVES: how many edges the file must give;
//   CLOSED: how many of them must be closed (their ends within TOL);
//   TOL: the largest distance allowed (the problem's length unit).
// Prints the edges, the points checked and the largest distance to each
// surface; exits 1 when a count or a distance is wrong.
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_CheckIterator.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>
#include <XSControl_WorkSession.hxx>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

const int kSamples = 1000; // points per edge

// The distance of p to the two surfaces of a case, in closed form.
struct Case {
    const char *name;
    double (*distance[2])(const gp_Pnt &p);
};

// Viviani: the cylinder (x - 1)^2 + y^2 = 1 and the sphere of radius 2.
double viviani_cylinder(const gp_Pnt &p)
{
    return std::fabs(std::hypot(p.X() - 1, p.Y()) - 1);
}
double viviani_sphere(const gp_Pnt &p)
{
    return std::fabs(std::sqrt(p.X() * p.X() + p.Y() * p.Y() + p.Z() * p.Z()) - 2);
}
// Two cylinders: x^2 + y^2 = 1 upright, x^2 + z^2 = 0.49 lying.
double upright(const gp_Pnt &p)
{
    return std::fabs(std::hypot(p.X(), p.Y()) - 1);
}
double lying(const gp_Pnt &p)
{
    return std::fabs(std::hypot(p.X(), p.Z()) - 0.7);
}

const Case kCases[] = {
    {"viviani", {viviani_cylinder, viviani_sphere}},
    {"cylinders", {upright, lying}},
};

bool ends_with(const std::string &s, const char *tail)
{
    const size_t n = std::strlen(tail);
    return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// The file's shape through OpenCASCADE's STEP or IGES reader, which must
// find no fault in it (a syntax or a schema error).
bool read_shape(const std::string &path, TopoDS_Shape &shape)
{
    STEPControl_Reader step;
    IGESControl_Reader iges;
    XSControl_Reader &reader = ends_with(path, ".step")
                                   ? static_cast<XSControl_Reader &>(step)
                                   : static_cast<XSControl_Reader &>(iges);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        return false;
    if (!reader.WS()->ModelCheckList().IsEmpty(Standard_True)) {
        std::fprintf(stderr, "read_curves: %s: the reader finds faults\n", path.c_str());
        reader.PrintCheckLoad(Standard_True, IFSelect_ItemsByEntity);
        return false;
    }
    if (reader.TransferRoots() == 0)
        return false;
    shape = reader.OneShape();
    return !shape.IsNull();
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 6) {
        std::fprintf(stderr, "usage: read_curves viviani|cylinders CURVES CLOSED TOL FILE\n");
        return 2;
    }
    const Case *c = nullptr;
    for (const Case &k : kCases)
        if (std::strcmp(k.name, argv[1]) == 0)
            c = &k;
    const int want_curves = std::atoi(argv[2]);
    const int want_closed = std::atoi(argv[3]);
    const double tol = std::atof(argv[4]);
    const std::string path = argv[5];
    TopoDS_Shape shape;
    if (!c || !read_shape(path, shape)) {
        std::fprintf(stderr, "read_curves: %s: an unknown case, or the file was not read\n", path.c_str());
        return 1;
    }
    int edges = 0, points = 0, closed = 0, periodic = 0;
    double worst[2] = {0, 0};
    for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next(), edges++) {
        Standard_Real first, last;
        Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(e.Current()), first, last);
        if (curve.IsNull())
            continue;
        closed += curve->Value(first).Distance(curve->Value(last)) <= tol;
        periodic += curve->IsPeriodic();
        for (int k = 0; k <= kSamples; k++, points++) {
            const gp_Pnt p = curve->Value(first + (last - first) * k / kSamples);
            for (int s = 0; s < 2; s++)
                worst[s] = std::fmax(worst[s], c->distance[s](p));
        }
    }
    std::printf("%s: %d edges (%d closed, %d periodic), %d points, largest distances %.3g and "
                "%.3g\n",
                path.c_str(), edges, closed, periodic, points, worst[0], worst[1]);
    const bool ok = edges == want_curves && closed == want_closed &&
                    points == edges * (kSamples + 1) && worst[0] <= tol && worst[1] <= tol;
    if (!ok)
        std::printf("read_curves: FAIL (want %d edges, %d closed, distances <= %g)\n", want_curves,
                    want_closed, tol);
    return ok ? 0 : 1;
}
