#include "ui/design/trimmed_region_guard.h"

#include "ui/design/design_session.h"

#include "core/design/session_chain.h"

#include <QElapsedTimer>

namespace trimlab::ui {

namespace {

/// How far inside the surface a trim test ray starts, relative to the mesh's bounding
/// radius: far above float rounding of the positions, far below any feature.
constexpr double kTrimTestOffset = 1e-5;

} // namespace

std::optional<QString> TrimmedRegionGuard::refuseDrag(const DesignSession& session, StaticRule baseRule,
                                                      const BrushDrag& drag)
{
    return refuseSample(session, baseRule,
                        TrimmedRegionCheck::sample(drag.stroke().region().vertices,
                                                   session.timeline().base().triangles.at(drag.pick().triangle)));
}

// The first moved vertex stands in for the brush's grabbed triangle.
std::optional<QString> TrimmedRegionGuard::refuseControlEdit(const DesignSession& session, StaticRule baseRule,
                                                             const timeline::Frame& frame)
{
    if (frame.vertices.empty())
        return std::nullopt;
    const std::uint32_t first = frame.vertices.front();
    return refuseSample(session, baseRule, TrimmedRegionCheck::sample(frame.vertices, glm::uvec3(first)));
}

std::optional<QString> TrimmedRegionGuard::refuseSample(const DesignSession& session, StaticRule baseRule,
                                                        const std::vector<std::uint32_t>& sample)
{
    const timeline::Timeline& history = session.timeline();
    if (history.sets().empty() || !forbidsDeformingTrimmedParts(history.sets().back().rule))
        return std::nullopt;
    QElapsedTimer timer;
    timer.start();
    if (!m_check || m_checkRevision != session.revision() || m_checkBaseRule != baseRule) {
        m_check = std::make_unique<TrimmedRegionCheck>(
            dynamicChainTo(history, session.lastFrame(), baseRule, session.modelMatrix()), session.modelMatrix());
        m_checkRevision = session.revision();
        m_checkBaseRule = baseRule;
    }
    const std::vector<std::uint32_t> off = m_check->trimmedOff(session.topology(), history.currentPositions(), sample,
                                                               kTrimTestOffset * session.baseBounds().radius());
    m_lastCheckMs = double(timer.nsecsElapsed()) * 1e-6;
    if (off.empty())
        return std::nullopt;
    return tr("Homogeneous confluent rule: this part was trimmed off and may not be deformed (thesis 8.1.1). Start a "
              "new set with another rule to deform it.");
}

} // namespace trimlab::ui
