// The wording of mesh_validation.h: trimUnavailableReason and formatReport.
#include "core/mesh/mesh_validation.h"

#include "core/mesh/reader_support.h"

#include <iomanip>
#include <sstream>

namespace trimlab {

namespace {

std::string times(std::uint32_t n)
{
    return n == 1 ? "once" : n == 2 ? "twice" : std::to_string(n) + " times";
}

// "between vertices 3 and 4" for a single edge, "first between ..." for several.
std::string firstEdge(const DefectSamples<MeshEdge>& edges)
{
    const MeshEdge& e = edges.first.front();
    return std::string(edges.count == 1 ? "" : "first ") + "between vertices " + std::to_string(e.a) + " and " +
           std::to_string(e.b);
}

template <class T>
std::string firstItem(const DefectSamples<T>& items, const char* noun)
{
    return std::string(items.count == 1 ? "" : "first: ") + noun + ' ' + std::to_string(items.first.front());
}

std::string unbalancedReason(const DefectSamples<MeshEdge>& edges)
{
    const MeshEdge& e = edges.first.front();
    return "Trimming needs every edge to be used equally often in both directions: " +
           countNoun(edges.count, "edge is", "edges are") + " not (" + firstEdge(edges) + ", used " + times(e.forward) +
           " from " + std::to_string(e.a) + " to " + std::to_string(e.b) + " and " +
           (e.backward == 0 ? "never" : times(e.backward)) +
           " back). Remove the extra faces or fix their "
           "orientation to use the trim modes.";
}

std::string edgeList(const DefectSamples<MeshEdge>& edges)
{
    std::string text;
    for (const MeshEdge& e : edges.first)
        text += (text.empty() ? "" : ", ") + std::to_string(e.a) + "-" + std::to_string(e.b);
    return text;
}

template <class T>
std::string itemList(const DefectSamples<T>& items)
{
    std::string text;
    for (const T& item : items.first)
        text += (text.empty() ? "" : ", ") + std::to_string(item);
    return text;
}

template <class T>
void writeDefect(std::ostringstream& out, const char* label, const DefectSamples<T>& defect, const std::string& list)
{
    out << "  " << std::left << std::setw(24) << (std::string(label) + ':') << defect.count;
    if (defect.any())
        out << " (first: " << list << (defect.count > defect.first.size() ? ", ..." : "") << ')';
    out << '\n';
}

void writeLine(std::ostringstream& out, const char* label, const std::string& value)
{
    out << "  " << std::left << std::setw(24) << (std::string(label) + ':') << value << '\n';
}

std::string vec3Text(const glm::dvec3& v)
{
    std::ostringstream text;
    text << std::setprecision(6) << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return text.str();
}

std::string boundsText(const Bounds& bounds)
{
    if (!bounds.valid())
        return "empty";
    const glm::dvec3 size = bounds.max - bounds.min;
    std::ostringstream text;
    text << std::setprecision(6) << "min " << vec3Text(bounds.min) << ", max " << vec3Text(bounds.max) << ", size "
         << size.x << " x " << size.y << " x " << size.z;
    return text.str();
}

} // namespace

std::string MeshValidationReport::trimUnavailableReason() const
{
    if (triangleCount == 0)
        return "Trimming needs a closed surface, but the mesh has no triangles.";
    if (outOfRangeFaces.any())
        return "Trimming needs valid faces: " + countNoun(outOfRangeFaces.count, "face references", "faces reference") +
               " vertices that do not exist (" + firstItem(outOfRangeFaces, "face") +
               "). Repair or re-export the mesh to use the trim modes.";
    if (nonFiniteVertices.any())
        return "Trimming needs finite coordinates: " +
               countNoun(nonFiniteVertices.count, "vertex has", "vertices have") + " NaN or infinite coordinates (" +
               firstItem(nonFiniteVertices, "vertex") + "). Repair or remove them to use the trim modes.";
    if (boundaryEdges.any())
        return "Trimming needs a closed surface: " + countNoun(boundaryEdges.count, "boundary edge", "boundary edges") +
               " (" + firstEdge(boundaryEdges) +
               "). Close the holes (Edit ▸ Close Holes, --close-holes, or a mesh editor) to use the trim modes.";
    if (inconsistentEdges.any())
        return "Trimming needs consistently oriented faces: " +
               countNoun(inconsistentEdges.count, "edge is", "edges are") + " used twice in the same direction (" +
               firstEdge(inconsistentEdges) +
               "). Make the face orientation consistent (e.g. recalculate normals outside in a mesh editor) to use "
               "the trim modes.";
    if (unbalancedEdges.any())
        return unbalancedReason(unbalancedEdges);
    return {};
}

std::string formatReport(const MeshValidationReport& report, const std::string& name)
{
    std::ostringstream out;
    out << std::setprecision(6) << name << '\n';
    writeLine(out, "vertices", std::to_string(report.vertexCount));
    writeLine(out, "triangles", std::to_string(report.triangleCount));
    writeLine(out, "edges", std::to_string(report.edgeCount));
    writeLine(out, "bounding box", boundsText(report.bounds));
    writeLine(out, "components", std::to_string(report.componentCount));
    writeLine(out, "closed", report.closed() ? "yes" : "no");
    writeLine(out, "manifold", report.manifold() ? "yes" : "no");
    const char* notClosedManifold = "n/a (not a closed manifold)";
    writeLine(out, "Euler characteristic",
              report.eulerCharacteristic ? std::to_string(*report.eulerCharacteristic) : notClosedManifold);
    writeLine(out, "genus",
              report.genus                 ? std::to_string(*report.genus)
              : report.eulerCharacteristic ? "n/a (inconsistent orientation)"
                                           : notClosedManifold);
    std::ostringstream volume;
    volume << std::setprecision(6) << report.signedVolume;
    writeLine(out, "signed volume", volume.str() + (report.closed() ? "" : " (not closed: not meaningful)"));
    writeDefect(out, "boundary edges", report.boundaryEdges, edgeList(report.boundaryEdges));
    writeDefect(out, "non-manifold edges", report.nonManifoldEdges, edgeList(report.nonManifoldEdges));
    writeDefect(out, "non-manifold vertices", report.nonManifoldVertices, itemList(report.nonManifoldVertices));
    writeDefect(out, "inconsistent edges", report.inconsistentEdges, edgeList(report.inconsistentEdges));
    writeDefect(out, "unbalanced edges", report.unbalancedEdges, edgeList(report.unbalancedEdges));
    writeDefect(out, "degenerate faces", report.degenerateFaces, itemList(report.degenerateFaces));
    writeDefect(out, "unreferenced vertices", report.unreferencedVertices, itemList(report.unreferencedVertices));
    writeDefect(out, "non-finite vertices", report.nonFiniteVertices, itemList(report.nonFiniteVertices));
    writeDefect(out, "out-of-range faces", report.outOfRangeFaces, itemList(report.outOfRangeFaces));
    if (report.trimmable())
        out << "trim modes: available\n";
    else
        out << "trim modes: unavailable \xE2\x80\x94 " << report.trimUnavailableReason() << '\n';
    return out.str();
}

} // namespace trimlab
