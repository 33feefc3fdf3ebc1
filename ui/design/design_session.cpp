#include "ui/design/design_session.h"

#include <algorithm>

namespace trimlab::ui {

DesignSession::DesignSession(timeline::Timeline history, const glm::dmat4& modelMatrix, QUndoStack& undoStack,
                             QObject* parent)
    : QObject(parent),
      m_timeline(std::move(history)),
      m_topology(std::make_unique<deform::BrushTopology>(m_timeline.base())),
      m_model(modelMatrix),
      m_baseBounds(computeBounds(m_timeline.base())),
      m_undo(&undoStack),
      m_shownFrame(m_timeline.frameCount() - 1)
{
    if (m_timeline.hasSurface()) {
        m_surface = std::make_unique<EditableSurface>(*m_timeline.surface());
        syncSurface();
    }
}

DesignSession::~DesignSession() = default;

const std::vector<glm::vec3>& DesignSession::shownPositions() const
{
    // The last frame is kept up to date by the timeline; only earlier frames are rebuilt.
    return showsLastFrame() ? m_timeline.currentPositions() : m_scrubbed;
}

void DesignSession::showFrame(int frame)
{
    frame = std::clamp(frame, 0, lastFrame());
    if (frame == m_shownFrame)
        return;
    m_shownFrame = frame;
    if (showsLastFrame())
        m_scrubbed = {};
    else
        m_scrubbed = m_timeline.positionsAt(frame);
    syncSurface();
    emit shownFrameChanged(frame);
}

void DesignSession::syncSurface()
{
    if (!m_surface)
        return;
    if (showsLastFrame()) {
        const std::vector<glm::dvec3>& points = m_timeline.currentControlPoints();
        if (points != m_surface->controlPoints())
            m_surface->setControlPoints(points);
    } else {
        m_surface->setControlPoints(m_timeline.controlPointsAt(m_shownFrame));
    }
}

void DesignSession::appendFrame(timeline::Frame frame)
{
    m_timeline.appendFrame(std::move(frame));
    afterEdit();
}

timeline::Frame DesignSession::removeLastFrame()
{
    timeline::Frame frame = m_timeline.removeLastFrame();
    afterEdit();
    return frame;
}

void DesignSession::startSet(DynamicRule rule)
{
    m_timeline.startSet(rule);
    afterEdit();
}

void DesignSession::removeLastSetIfEmpty()
{
    m_timeline.removeLastSetIfEmpty();
    afterEdit();
}

void DesignSession::setRule(int set, DynamicRule rule)
{
    m_timeline.setRule(set, rule);
    afterEdit();
}

// An edit changes the last frame, so the view goes there: what the designer just did is
// what is shown.
void DesignSession::afterEdit()
{
    ++m_revision;
    m_shownFrame = lastFrame();
    m_scrubbed = {};
    syncSurface();
    emit historyChanged(); // one signal: listeners refresh the shown frame with the history
}

} // namespace trimlab::ui
