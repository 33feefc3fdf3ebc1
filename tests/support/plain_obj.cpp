#include "plain_obj.h"

#include <cstdio>
#include <fstream>

namespace trimlab::test {

bool writePlainObj(const TriangleMesh& mesh, const QString& path)
{
    std::ofstream out(path.toStdString());
    char line[128];
    for (const glm::vec3& p : mesh.positions) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
        out << line;
    }
    for (const glm::uvec3& t : mesh.triangles)
        out << "f " << t.x + 1 << ' ' << t.y + 1 << ' ' << t.z + 1 << '\n';
    out.flush();
    return bool(out);
}

} // namespace trimlab::test
