#include "MeshDecimation.h"

#include "mesh/import/MeshTopology.h"

#include "DecimationWeld.h"

#include <QCoreApplication>
#include <QLocale>
#include <QStringList>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshDecimationWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshDecimation)
};

namespace {

using decimation::isFaceted;
using decimation::ModFlipGuardT;
using decimation::OmMesh;
using decimation::rebuild;
using decimation::Weld;
using decimation::weldByPosition;

// A collapse may turn a neighbouring face by at most this much: enough to
// let curved surfaces coarsen, too little for a face to flip or fold over.
constexpr double kMaxFaceTurnDeg = 60.0;

bool finite(const glm::vec3 &p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// What adding the triangles to OpenMesh left out.
struct AddReport {
    std::size_t collapsed =
        0; // two corners at one position (a UV sphere's poles): invisible, dropped silently
    std::size_t nonFinite = 0;   // a corner at NaN or infinity
    std::size_t nonManifold = 0; // an edge or vertex OpenMesh cannot take
};

// Adds every triangle OpenMesh accepts; faceTriangle[f] = the input triangle of face f.
AddReport buildOpenMesh(const MeshData &mesh, const Weld &w, OmMesh &om,
                        std::vector<std::uint32_t> &faceTriangle)
{
    AddReport report;
    om.reserve(w.firstGpu.size(), mesh.indices.size() / 2 + 3, mesh.triangleCount());
    for (std::uint32_t gpu : w.firstGpu) {
        const glm::vec3 &p = mesh.positions[gpu];
        om.add_vertex(OmMesh::Point(p.x, p.y, p.z));
    }
    faceTriangle.reserve(mesh.triangleCount());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        OpenMesh::VertexHandle v[3];
        bool ok = true;
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t gpu = mesh.indices[3 * t + c];
            ok = ok && finite(mesh.positions[gpu]);
            v[c] = OpenMesh::VertexHandle(int(w.weldedOf[gpu]));
        }
        if (!ok) {
            ++report.nonFinite;
            continue;
        }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
            ++report.collapsed;
            continue;
        }
        // add_face's own first checks, made here so that refused faces are
        // counted instead of printed: every corner must be on the border of
        // what is there already (or unused), and no directed edge may already
        // have a face (a third face on an edge, or a duplicate face).
        for (int c = 0; c < 3 && ok; ++c) {
            ok = om.is_boundary(v[c]);
            const OpenMesh::HalfedgeHandle h = om.find_halfedge(v[c], v[(c + 1) % 3]);
            ok = ok && (!h.is_valid() || om.is_boundary(h));
        }
        if (ok && om.add_face(v[0], v[1], v[2]).is_valid())
            faceTriangle.push_back(std::uint32_t(t));
        else
            ++report.nonManifold;
    }
    return report;
}

void prepareForDecimation(OmMesh &om)
{
    om.request_vertex_status();
    om.request_edge_status();
    om.request_face_status();
    // Boundary vertices stay where they are: open edges keep their exact
    // outline (and parts that only touch along a border do not crack apart).
    for (OpenMesh::VertexHandle v : om.vertices())
        if (om.is_boundary(v))
            om.status(v).set_locked(true);
    // The flip guard measures against face normals.
    om.request_face_normals();
    om.update_face_normals();
}

std::size_t liveFaces(const OmMesh &om)
{
    std::size_t faces = 0;
    for (OpenMesh::FaceHandle f : om.all_faces())
        faces += om.status(f).deleted() ? 0 : 1;
    return faces;
}

QString count(std::size_t n)
{
    return QLocale::c().toString(qulonglong(n));
}

// Reports the collapses done against the ones needed for the coarsest level,
// and stops the Decimater when the caller says so.
class ProgressObserver : public OpenMesh::Decimater::Observer
{
public:
    ProgressObserver(const DecimationProgress &progress, std::size_t collapses)
        : Observer(std::max<std::size_t>(1, collapses / 50))
        , m_progress(progress)
        , m_collapses(std::max<std::size_t>(1, collapses))
    {
    }
    void notify(std::size_t step) override
    {
        m_cancelled = m_cancelled || !m_progress(std::min(1.0, double(step) / double(m_collapses)));
    }
    bool abort() const override { return m_cancelled; }
    bool cancelled() const { return m_cancelled; }

private:
    const DecimationProgress &m_progress;
    std::size_t m_collapses;
    bool m_cancelled = false;
};

// Sorts out the levels that need no decimation: a fraction out of range (said
// in a note), 1, or nothing to decimate get the mesh as it is. Returns the
// indices of the others.
std::vector<std::size_t> levelsToDecimate(const MeshData &mesh,
                                          const std::vector<double> &fractions,
                                          std::vector<MeshData> &levels, QStringList &notes)
{
    std::vector<std::size_t> todo;
    for (std::size_t i = 0; i < fractions.size(); ++i) {
        const double fraction = fractions[i];
        if (!(fraction > 0.0 && fraction <= 1.0)) {
            notes << MeshDecimationWords::tr(
                         "detail must be in (0, 1] (got %1); mesh left as it is")
                         .arg(fraction);
            levels[i] = mesh;
        } else if (fraction == 1.0 || mesh.indices.empty()) {
            levels[i] = mesh;
        } else {
            todo.push_back(i);
        }
    }
    return todo;
}

void noteLeftOut(const AddReport &added, QStringList &notes)
{
    if (added.nonManifold > 0)
        notes << MeshDecimationWords::tr(
                     "%1 non-manifold triangles (an edge with more than two faces, or a "
                     "vertex joining "
                     "separate fans) could not be decimated and were left out")
                     .arg(count(added.nonManifold));
    if (added.nonFinite > 0)
        notes << MeshDecimationWords::tr("%1 triangles with non-finite corners left out")
                     .arg(count(added.nonFinite));
}

// The quadric module picks the collapses, the flip guard refuses those that
// would fold a face. False when the Decimater could not start.
bool setUpModules(OpenMesh::Decimater::DecimaterT<OmMesh> &decimater)
{
    OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle quadric;
    ModFlipGuardT<OmMesh>::Handle flipGuard;
    decimater.add(quadric);
    decimater.module(quadric).unset_max_err(); // the face budget decides, not an error bound
    decimater.add(flipGuard);
    decimater.module(flipGuard).set_max_normal_deviation(kMaxFaceTurnDeg);
    return decimater.initialize();
}

// What one decimation run, from the input down to the coarsest level, works on.
struct LevelRun {
    const MeshData &mesh;
    const Weld &weld;
    OmMesh &om;
    const std::vector<std::uint32_t> &faceTriangle;
    const std::vector<double> &fractions;
    const DecimationProgress &progress;
};

// Decimates run.om level by level and fills levels[i] for each i in todo.
// False when the caller cancelled through progress (levels then partly set).
bool decimateLevels(const LevelRun &run, std::vector<std::size_t> todo,
                    std::vector<MeshData> &levels, QStringList &notes)
{
    const std::vector<double> &fractions = run.fractions;
    OmMesh &om = run.om;
    prepareForDecimation(om);
    OpenMesh::Decimater::DecimaterT<OmMesh> decimater(om);
    const bool ready = setUpModules(decimater);

    // Finest first: each coarser level goes on from the one before (the
    // quadrics carry over), so all levels cost one run to the coarsest.
    std::stable_sort(todo.begin(), todo.end(),
                     [&](std::size_t a, std::size_t b) { return fractions[a] > fractions[b]; });
    const bool faceted = isFaceted(run.mesh);
    std::size_t faces = run.faceTriangle.size();
    // Each collapse removes about two faces: that many to reach the coarsest level.
    const double coarsest = fractions[todo.back()];
    std::unique_ptr<ProgressObserver> observer;
    if (run.progress) {
        const auto collapses = std::size_t(double(faces) * (1.0 - coarsest) / 2.0);
        observer = std::make_unique<ProgressObserver>(run.progress, collapses);
        decimater.set_observer(observer.get());
    }
    for (std::size_t i : todo) {
        const std::size_t target = std::max<std::size_t>(
            1, std::size_t(std::llround(fractions[i] * double(run.mesh.triangleCount()))));
        if (ready && target < faces) {
            // The decimater counts the faces deleted so far (no garbage
            // collection here: face handles index faceTriangle) as present.
            decimater.decimate_to_faces(0, target + (om.n_faces() - faces));
            faces = liveFaces(om);
            if (observer && observer->cancelled()) {
                decimater.set_observer(nullptr);
                return false;
            }
        }
        // Some slack: collapses remove two faces at a time, and closed
        // pieces cannot shrink below a tetrahedron.
        if (faces > target + target / 20 + 4)
            notes << MeshDecimationWords::tr(
                         "decimation stopped at %1 triangles (asked for %2): every "
                         "further collapse would "
                         "fold a face or break the surface")
                         .arg(count(faces), count(target));
        levels[i] = rebuild(run.mesh, run.weld, om, run.faceTriangle, faceted);
    }
    if (observer)
        decimater.set_observer(nullptr);
    return true;
}

} // namespace

DecimatedLevels decimateMeshLevels(const MeshData &mesh, const std::vector<double> &fractions,
                                   const DecimationProgress &progress)
{
    std::vector<MeshData> levels(fractions.size());
    QStringList notes;
    std::vector<std::size_t> todo = levelsToDecimate(mesh, fractions, levels, notes);
    const auto finish = [&] {
        return DecimatedLevels{std::move(levels), notes.join(QStringLiteral("; "))};
    };
    if (todo.empty())
        return finish();
    if (!mesh.isValid()) {
        notes << MeshDecimationWords::tr(
            "invalid mesh (index out of range or normals missing); not decimated");
        for (std::size_t i : todo)
            levels[i] = mesh;
        return finish();
    }

    const Weld weld = weldByPosition(mesh);
    OmMesh om;
    std::vector<std::uint32_t> faceTriangle;
    const AddReport added = buildOpenMesh(mesh, weld, om, faceTriangle);
    if (faceTriangle.empty()) {
        notes << MeshDecimationWords::tr(
            "no triangle could be taken for decimation (all degenerate, non-finite or "
            "non-manifold); mesh left as it is");
        for (std::size_t i : todo)
            levels[i] = mesh;
        return finish();
    }
    noteLeftOut(added, notes);

    const LevelRun run{mesh, weld, om, faceTriangle, fractions, progress};
    if (!decimateLevels(run, std::move(todo), levels, notes)) {
        notes = QStringList{QStringLiteral("cancelled")};
        levels.assign(fractions.size(), MeshData{});
    }
    return finish();
}

DecimatedMesh decimateMesh(const MeshData &mesh, double fraction,
                           const DecimationProgress &progress)
{
    DecimatedLevels decimated = decimateMeshLevels(mesh, {fraction}, progress);
    return {std::move(decimated.levels.front()), std::move(decimated.note)};
}

bool isClosedMesh(const MeshData &mesh)
{
    if (!mesh.isValid() || mesh.indices.empty())
        return false;
    const Weld weld = weldByPosition(mesh);
    PolygonMesh polygons;
    polygons.positions.resize(weld.firstGpu.size());
    polygons.reserve(weld.firstGpu.size(), mesh.triangleCount(), mesh.indices.size());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t a = weld.weldedOf[mesh.indices[3 * t]],
                            b = weld.weldedOf[mesh.indices[3 * t + 1]],
                            c = weld.weldedOf[mesh.indices[3 * t + 2]];
        if (a == b || b == c || c == a)
            continue; // no area, no edges of the surface (a UV sphere's pole triangles)
        polygons.cornerPosition.insert(polygons.cornerPosition.end(), {a, b, c});
        polygons.faceStart.push_back(std::uint32_t(polygons.cornerPosition.size()));
    }
    return isClosedSurface(polygons);
}

} // namespace phonglab
