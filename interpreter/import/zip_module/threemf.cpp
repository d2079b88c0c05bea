// 3MF (3D Manufacturing Format: a zip of XML parts), read with Debian's
// lib3mf 1.8 (the library OpenSCAD 2021.01 links), in the zip module
// (zip_module.hpp). The format's meaning:
// every build item is a part, its object's meshes placed by the item's
// transform and, through components objects, by theirs; the model's unit
// scales to millimetres. OpenSCAD 2021.01's reading (MeshReading::openscad)
// is different and kept for .scad files: every mesh object once, where it
// is stored, the unit and the build ignored — with a warning when that
// changes the model.
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <Model/COM/NMR_DLLInterfaces.h>

#include "interpreter/import/zip_module/zip_module.hpp"

namespace kerf::eval::mesh_format {

namespace {

using namespace NMR;

// A lib3mf handle, released when it goes.
struct Handle {
    PLib3MFBase* p = nullptr;
    Handle() = default;
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() {
        if (p) lib3mf_release(p);
    }
};

// lib3mf's message for a failed call on `h` (its last error), or the code.
std::string lib3mf_message(PLib3MFBase* h, HRESULT code) {
    DWORD err = 0;
    LPCSTR msg = nullptr;
    if (h && lib3mf_getlasterror(h, &err, &msg) == LIB3MF_OK && msg && *msg) return msg;
    char buf[32];
    std::snprintf(buf, sizeof buf, "error 0x%08x", static_cast<unsigned>(code));
    return buf;
}

void check(HRESULT r, PLib3MFBase* h, const char* what) {
    if (r != LIB3MF_OK) throw MeshFormatError(std::string("not a readable 3MF file: ") + what + ": " + lib3mf_message(h, r));
}

double unit_mm(DWORD unit) {
    switch (unit) {
        case MODELUNIT_MICROMETER: return 0.001;
        case MODELUNIT_CENTIMETER: return 10;
        case MODELUNIT_INCH: return 25.4;
        case MODELUNIT_FOOT: return 304.8;
        case MODELUNIT_METER: return 1000;
        default: return 1;
    }
}

const char* unit_name(DWORD unit) {
    switch (unit) {
        case MODELUNIT_MICROMETER: return "micron";
        case MODELUNIT_CENTIMETER: return "centimeter";
        case MODELUNIT_INCH: return "inch";
        case MODELUNIT_FOOT: return "foot";
        case MODELUNIT_METER: return "meter";
        default: return "millimeter";
    }
}

// An affine map of 3MF (3 rows of 4: x' = row 0 · (x, y, z, 1), ...).
using Affine = glm::dmat4;

Affine affine(const MODELTRANSFORM& t) {
    Affine m(1.0);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = t.m_fFields[r][c];
    return m;
}

class Reader {
public:
    Reader(const MeshReading& how, double mm) : how_(how), mm_(mm) {}

    // The mesh of a mesh object, mapped by `m` (and the unit).
    void add_mesh(PLib3MFBase* object, const Affine& m) {
        DWORD nv = 0, nt = 0;
        check(lib3mf_meshobject_getvertexcount(object, &nv), object, "vertices");
        check(lib3mf_meshobject_gettrianglecount(object, &nt), object, "triangles");
        if (nt > how_.max_faces - std::min<std::uint64_t>(faces_, how_.max_faces))
            throw MeshLimitError("more than " + std::to_string(how_.max_faces) + " triangles (--max-list)");
        faces_ += nt;
        if (nt == 0) return;
        std::vector<MODELMESHVERTEX> v(nv);
        std::vector<MODELMESHTRIANGLE> t(nt);
        check(lib3mf_meshobject_getvertices(object, v.data(), nv, nullptr), object, "vertices");
        check(lib3mf_meshobject_gettriangleindices(object, t.data(), nt, nullptr), object, "triangles");
        graph::PolygonMesh part;
        part.points.reserve(nv);
        for (const MODELMESHVERTEX& p : v) {
            const glm::dvec4 q = m * glm::dvec4(p.m_fPosition[0], p.m_fPosition[1], p.m_fPosition[2], 1.0);
            part.points.emplace_back(mm_ * glm::dvec3(q));
        }
        part.faces.reserve(nt);
        for (const MODELMESHTRIANGLE& f : t) part.faces.push_back({f.m_nIndices[0], f.m_nIndices[1], f.m_nIndices[2]});
        // A map that mirrors turns the faces clockwise: turn them back.
        if (glm::determinant(glm::dmat3(m)) < 0)
            for (auto& f : part.faces) std::swap(f[1], f[2]);
        out.parts.push_back(std::move(part));
    }

    // An object of the build: a mesh, or components placing other objects.
    void add_object(PLib3MFBase* object, const Affine& m, int depth) {
        BOOL is_mesh = false, is_components = false;
        check(lib3mf_object_ismeshobject(object, &is_mesh), object, "object");
        if (is_mesh) return add_mesh(object, m);
        check(lib3mf_object_iscomponentsobject(object, &is_components), object, "object");
        if (!is_components) return;
        if (depth > 32) throw MeshFormatError("components nested more than 32 deep");
        DWORD n = 0;
        check(lib3mf_componentsobject_getcomponentcount(object, &n), object, "components");
        for (DWORD i = 0; i < n; ++i) {
            Handle component, inner;
            check(lib3mf_componentsobject_getcomponent(object, i, &component.p), object, "component");
            check(lib3mf_component_getobjectresource(component.p, &inner.p), component.p, "component");
            MODELTRANSFORM t;
            check(lib3mf_component_gettransform(component.p, &t), component.p, "component");
            add_object(inner.p, m * affine(t), depth + 1);
        }
    }

    ImportedMesh out;

private:
    const MeshReading& how_;
    double mm_;
    std::uint64_t faces_ = 0;
};

// Moves an iterator on; false at its end.
template <class F>
bool next(PLib3MFBase* it, F movenext) {
    BOOL more = false;
    check(movenext(it, &more), it, "iterating");
    return more;
}

}  // namespace

ImportedMesh lib3mf_read(const std::string& path, const MeshReading& how) {
    Handle model, reader;
    check(lib3mf_createmodel(&model.p), nullptr, "creating a model");
    check(lib3mf_model_queryreader(model.p, "3mf", &reader.p), model.p, "creating a reader");
    check(lib3mf_reader_readfromfileutf8(reader.p, path.c_str()), reader.p, "reading");
    DWORD unit = MODELUNIT_MILLIMETER;
    check(lib3mf_model_getunit(model.p, &unit), model.p, "unit");
    Reader r(how, how.openscad ? 1 : unit_mm(unit));

    // The build: the parts of the format's meaning, and what OpenSCAD's
    // reading would leave out (the warnings below).
    Handle items;
    check(lib3mf_model_getbuilditems(model.p, &items.p), model.p, "build items");
    std::size_t n_items = 0;
    bool placed = false;
    while (next(items.p, lib3mf_builditemiterator_movenext)) {
        Handle item, object;
        check(lib3mf_builditemiterator_getcurrent(items.p, &item.p), items.p, "build item");
        check(lib3mf_builditem_getobjectresource(item.p, &object.p), item.p, "build item");
        MODELTRANSFORM t;
        check(lib3mf_builditem_getobjecttransform(item.p, &t), item.p, "build item");
        ++n_items;
        BOOL has = false, is_mesh = false;
        check(lib3mf_builditem_hasobjecttransform(item.p, &has), item.p, "build item");
        check(lib3mf_object_ismeshobject(object.p, &is_mesh), object.p, "object");
        placed |= has || !is_mesh;
        if (!how.openscad) r.add_object(object.p, affine(t), 0);
    }
    if (!how.openscad) {
        if (n_items == 0) throw MeshFormatError("the 3MF build has no items: nothing to make");
        return std::move(r.out);
    }

    Handle meshes;
    check(lib3mf_model_getmeshobjects(model.p, &meshes.p), model.p, "mesh objects");
    std::size_t n_meshes = 0;
    while (next(meshes.p, lib3mf_resourceiterator_movenext)) {
        Handle object;
        check(lib3mf_resourceiterator_getcurrent(meshes.p, &object.p), meshes.p, "mesh object");
        r.add_mesh(object.p, Affine(1.0));
        ++n_meshes;
    }
    if (unit != MODELUNIT_MILLIMETER)
        r.out.warnings.push_back(std::string("unit=\"") + unit_name(unit) +
                                 "\" is ignored (read as millimetres), as OpenSCAD 2021.01 ignores it");
    if (placed || n_items != n_meshes)
        r.out.warnings.push_back("the build (" + std::to_string(n_items) + " item(s), their transforms and components) " +
                                 "is not applied: each of the " + std::to_string(n_meshes) +
                                 " mesh object(s) is taken once where it is stored, as OpenSCAD 2021.01 takes it");
    return std::move(r.out);
}

}  // namespace kerf::eval::mesh_format
