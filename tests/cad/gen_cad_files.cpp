// Writes the CAD test files of tests/data/cad with OpenCASCADE's STEP and
// IGES writers, an independent writer for intercurve's reader (docs/testing.md,
// "CAD test files"). tests/test_cad.c states the same definitions on its own
// and checks what the reader gives against them; change both together.
//
// All lengths in millimetres. The surfaces:
//  - a bicubic B-spline patch: 5 x 4 control points P(i, j) = (10 i, 8 j,
//    z(i, j)), z = 2 ((3 i + 5 j) mod 4) - 3 + i j / 4; u knots 0 0 0 0 0.4 1 1
//    1 1, v knots 0 0 0 0 2 2 2 2;
//  - exact rational forms (GeomConvert) of a sphere (centre (5, -3, 12),
//    radius 7.5, axis (1, 1, 1)) and of a cylinder (centre (-2, 4, 1), radius
//    3, axis (0, 0.6, 0.8), v from -5 to 15);
//  - a plane, a cylinder, a cone, a sphere and a torus at the placements
//    below, and (STEP only) a surface of revolution, which the reader does
//    not read.
// usage: gen_cad_files OUTDIR
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeSegment.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax3.hxx>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

const double kTol = 1e-7; // the faces' tolerance (mm)

Handle(Geom_BSplineSurface) bicubic()
{
    TColgp_Array2OfPnt poles(1, 5, 1, 4);
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 4; j++)
            poles(i + 1, j + 1) =
                gp_Pnt(10.0 * i, 8.0 * j, 2.0 * ((3 * i + 5 * j) % 4) - 3.0 + 0.25 * i * j);
    TColStd_Array1OfReal uk(1, 3), vk(1, 2);
    TColStd_Array1OfInteger um(1, 3), vm(1, 2);
    uk(1) = 0; uk(2) = 0.4; uk(3) = 1;
    um(1) = 4; um(2) = 1; um(3) = 4;
    vk(1) = 0; vk(2) = 2;
    vm(1) = 4; vm(2) = 4;
    return new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3);
}

gp_Dir unit(double x, double y, double z) { return gp_Dir(x, y, z); }

Handle(Geom_Surface) nurbs_sphere()
{
    gp_Ax3 ax(gp_Pnt(5, -3, 12), unit(1, 1, 1), unit(1, -1, 0));
    Handle(Geom_SphericalSurface) s = new Geom_SphericalSurface(ax, 7.5);
    return GeomConvert::SurfaceToBSplineSurface(s);
}

Handle(Geom_Surface) nurbs_cylinder()
{
    gp_Ax3 ax(gp_Pnt(-2, 4, 1), unit(0, 0.6, 0.8), unit(1, 0, 0));
    Handle(Geom_CylindricalSurface) c = new Geom_CylindricalSurface(ax, 3);
    Handle(Geom_RectangularTrimmedSurface) t =
        new Geom_RectangularTrimmedSurface(c, 0.0, 2 * M_PI, -5.0, 15.0);
    return GeomConvert::SurfaceToBSplineSurface(t);
}

// The placed primitives, each with the parameter box its face covers.
struct Placed {
    Handle(Geom_Surface) surface;
    double u0, u1, v0, v1;
};

std::vector<Placed> primitives()
{
    std::vector<Placed> out;
    out.push_back({new Geom_Plane(gp_Ax3(gp_Pnt(1, 2, 3), unit(0, 1, 1), unit(1, 0, 0))), -4, 4,
                   -3, 3});
    out.push_back({new Geom_CylindricalSurface(
                       gp_Ax3(gp_Pnt(10, -4, 2), unit(0.6, 0, 0.8), unit(0, 1, 0)), 4),
                   0, 2 * M_PI, -2, 6});
    out.push_back({new Geom_ConicalSurface(
                       gp_Ax3(gp_Pnt(-3, 5, 1), unit(0, -0.6, 0.8), unit(1, 0, 0)), 0.4, 2.5),
                   0, 2 * M_PI, 0, 5});
    out.push_back({new Geom_SphericalSurface(
                       gp_Ax3(gp_Pnt(2, 2, -7), unit(1, 0, 0), unit(0, 0, 1)), 3.25),
                   0, 2 * M_PI, -M_PI / 2, M_PI / 2});
    out.push_back({new Geom_ToroidalSurface(
                       gp_Ax3(gp_Pnt(0, -6, 4), unit(0, 0.8, 0.6), unit(1, 0, 0)), 9, 2),
                   0, 2 * M_PI, 0, 2 * M_PI});
    return out;
}

Handle(Geom_Surface) revolution()
{
    Handle(Geom_TrimmedCurve) seg = GC_MakeSegment(gp_Pnt(4, 0, 0), gp_Pnt(6, 0, 5)).Value();
    return new Geom_SurfaceOfRevolution(seg, gp_Ax1(gp_Pnt(0, 0, 0), unit(0, 0, 1)));
}

TopoDS_Face face(const Handle(Geom_Surface) & s, double u0, double u1, double v0, double v1)
{
    return BRepBuilderAPI_MakeFace(s, u0, u1, v0, v1, kTol).Face();
}

TopoDS_Face face(const Handle(Geom_Surface) & s)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    return face(s, u0, u1, v0, v1);
}

TopoDS_Compound compound(const std::vector<TopoDS_Face> &faces)
{
    BRep_Builder b;
    TopoDS_Compound c;
    b.MakeCompound(c);
    for (const TopoDS_Face &f : faces)
        b.Add(c, f);
    return c;
}

bool write_step(const std::string &path, const std::vector<TopoDS_Face> &faces)
{
    STEPControl_Writer w;
    Interface_Static::SetCVal("write.step.unit", "MM");
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    if (w.Transfer(compound(faces), STEPControl_AsIs) != IFSelect_RetDone)
        return false;
    return w.Write(path.c_str()) == IFSelect_RetDone;
}

// IGES: the bicubic alone as a 128 (AddGeom), the others as faces (144 on a
// 128): every surface is made a B-spline first, as the reader reads 128s.
bool write_iges(const std::string &path, const std::vector<Handle(Geom_Surface)> &bare,
                const std::vector<TopoDS_Face> &faces)
{
    IGESControl_Controller::Init();
    IGESControl_Writer w("MM", 0);
    for (const Handle(Geom_Surface) &s : bare)
        w.AddGeom(s);
    for (const TopoDS_Face &f : faces)
        w.AddShape(f);
    w.ComputeModel();
    return w.Write(path.c_str());
}

Handle(Geom_Surface) as_bspline(const Placed &p)
{
    Handle(Geom_RectangularTrimmedSurface) t =
        new Geom_RectangularTrimmedSurface(p.surface, p.u0, p.u1, p.v0, p.v1);
    return GeomConvert::SurfaceToBSplineSurface(t);
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: gen_cad_files OUTDIR\n");
        return 1;
    }
    const std::string dir = argv[1];
    std::vector<TopoDS_Face> splines = {face(bicubic()), face(nurbs_sphere()),
                                        face(nurbs_cylinder())};
    std::vector<TopoDS_Face> prims, prims_as_splines;
    for (const Placed &p : primitives()) {
        prims.push_back(face(p.surface, p.u0, p.u1, p.v0, p.v1));
        Handle(Geom_Surface) b = as_bspline(p);
        prims_as_splines.push_back(face(b));
    }
    prims.push_back(face(revolution(), 0, 2 * M_PI, 0, 1));
    bool ok = write_step(dir + "/bspline.step", splines) &&
              write_step(dir + "/primitives.step", prims) &&
              write_iges(dir + "/bspline.igs", {bicubic()},
                         {face(nurbs_sphere()), face(nurbs_cylinder())}) &&
              write_iges(dir + "/primitives.igs", {}, prims_as_splines);
    if (!ok) {
        std::fprintf(stderr, "gen_cad_files: a writer failed\n");
        return 1;
    }
    return 0;
}
