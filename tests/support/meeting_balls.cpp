#include "meeting_balls.h"

#include "plain_obj.h"

#include "core/scene/shape_generators.h"

#include <QDir>

namespace trimlab::test {

bool writeMeetingBalls(const QString& folder)
{
    if (!QDir().mkpath(folder))
        return false;
    const double offsets[] = {1.4, 0.8, 0.5};
    for (int pose = 0; pose < 3; ++pose) {
        TriangleMesh balls = makeIcosphere(glm::dvec3(-offsets[pose], 0.0, 0.0), 1.0, 2);
        appendMesh(balls, makeIcosphere(glm::dvec3(offsets[pose], 0.1, 0.0), 1.0, 2));
        if (!writePlainObj(balls, QStringLiteral("%1/pose_%2.obj").arg(folder).arg(pose)))
            return false;
    }
    return true;
}

} // namespace trimlab::test
