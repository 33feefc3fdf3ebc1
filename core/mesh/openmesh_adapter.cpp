#include "core/mesh/openmesh_adapter.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <mutex>

namespace trimlab {

namespace {

// Silences omerr() (where OpenMesh reports "complex edge" and similar) for its lifetime.
// The stream is global, so conversions serialise on a mutex while it is switched off.
class QuietOpenMeshErrors {
public:
    QuietOpenMeshErrors() : m_lock(mutex()), m_wasEnabled(omerr().is_enabled()) { omerr().disable(); }
    ~QuietOpenMeshErrors()
    {
        if (m_wasEnabled)
            omerr().enable();
    }
    QuietOpenMeshErrors(const QuietOpenMeshErrors&) = delete;
    QuietOpenMeshErrors& operator=(const QuietOpenMeshErrors&) = delete;

private:
    static std::mutex& mutex()
    {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> m_lock;
    bool m_wasEnabled;
};

// The checks OpenMesh's add_face makes first, done here so that the usual rejections
// (non-manifold vertex or edge) happen without calling into it at all.
bool canAddFace(const OpenMeshTriMesh& mesh, const OpenMeshTriMesh::VertexHandle (&v)[3])
{
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
        return false;
    for (int i = 0; i < 3; ++i) {
        if (!mesh.is_boundary(v[i]))
            return false; // the vertex is surrounded already
        const auto halfedge = mesh.find_halfedge(v[i], v[(i + 1) % 3]);
        if (halfedge.is_valid() && !mesh.is_boundary(halfedge))
            return false; // the directed edge has a face already
    }
    return true;
}

} // namespace

OpenMeshConversion toOpenMesh(const TriangleMesh& mesh)
{
    OpenMeshConversion result;
    OpenMeshTriMesh& om = result.mesh;
    om.reserve(mesh.positions.size(), 3 * mesh.triangles.size() / 2, mesh.triangles.size());
    for (const glm::vec3& p : mesh.positions)
        om.add_vertex(OpenMeshTriMesh::Point(p.x, p.y, p.z));
    QuietOpenMeshErrors quiet;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        bool added = false;
        if (t[0] < mesh.positions.size() && t[1] < mesh.positions.size() && t[2] < mesh.positions.size()) {
            const OpenMeshTriMesh::VertexHandle v[3] = {OpenMeshTriMesh::VertexHandle(static_cast<int>(t[0])),
                                                        OpenMeshTriMesh::VertexHandle(static_cast<int>(t[1])),
                                                        OpenMeshTriMesh::VertexHandle(static_cast<int>(t[2]))};
            added = canAddFace(om, v) && om.add_face(v[0], v[1], v[2]).is_valid();
        }
        if (!added) {
            ++result.rejectedFaces;
            result.rejectedFaceIndices.push_back(f);
        }
    }
    return result;
}

TriangleMesh fromOpenMesh(const OpenMeshTriMesh& mesh)
{
    TriangleMesh out;
    out.positions.reserve(mesh.n_vertices());
    for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
        const auto& p = mesh.point(OpenMeshTriMesh::VertexHandle(static_cast<int>(i)));
        out.positions.emplace_back(p[0], p[1], p[2]);
    }
    out.triangles.reserve(mesh.n_faces());
    for (const auto face : mesh.faces()) {
        glm::uvec3 t(0);
        int k = 0;
        for (const auto vertex : face.vertices()) {
            if (k < 3)
                t[k] = static_cast<unsigned>(vertex.idx());
            ++k;
        }
        if (k == 3)
            out.triangles.push_back(t);
    }
    return out;
}

} // namespace trimlab
