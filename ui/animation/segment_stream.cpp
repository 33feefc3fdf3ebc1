#include "ui/animation/segment_stream.h"

#include "ui/common/background_task.h"

#include "core/animation/segment_coloring.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace trimlab::ui {

/// Everything a stream's jobs read and change (see SegmentStream::m_state).
struct SegmentStreamState {
    std::shared_ptr<const MeshAnimation> animation;
    SegmenterSettings settings;
    std::shared_ptr<AnimationSegmenter> segmenter;
    StreamStep step;
    std::shared_ptr<const SegmentationResult> result; ///< set by the completion job
};

namespace {

/// The animation's first pose alone: where a stream starts.
MeshAnimation firstPoseOf(const MeshAnimation& animation)
{
    MeshAnimation first;
    first.triangles = animation.triangles;
    first.poses.push_back(animation.poses.front());
    if (!animation.poseNames.empty())
        first.poseNames.push_back(animation.poseNames.front());
    if (!animation.poseTimes.empty())
        first.poseTimes.push_back(animation.poseTimes.front());
    return first;
}

/// On a worker: adds pose `pose` to the stream's segmenter (creating it for pose 0),
/// cleans with `h` and colors from the previous step.
void appendStreamPose(SegmentStreamState& state, std::size_t pose, double h, const TaskControl& control)
{
    const auto start = std::chrono::steady_clock::now();
    const MeshAnimation& animation = *state.animation;
    if (!state.segmenter) {
        state.segmenter = std::make_shared<AnimationSegmenter>(firstPoseOf(animation), state.settings);
        state.segmenter->run(control);
    } else {
        const std::string name = pose < animation.poseNames.size() ? animation.poseNames[pose] : std::string();
        state.segmenter->appendPose(animation.poses[pose], name, control);
    }
    const AnimationSegmenter& segmenter = *state.segmenter;
    VertexLabeling labeling = segmenter.segment(h);
    StreamStep& step = state.step;
    step.colors = step.labeling.labels.empty()
                      ? colorSegments(segmenter.graph(), labeling, segmenter.vertexAreas())
                      : propagateColors(segmenter.graph(), segmenter.vertexAreas(), step.labeling, step.colors, labeling);
    step.labeling = std::move(labeling);
    step.processed = int(pose) + 1;
    step.times = segmenter.times();
    step.stepMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

SegmentStream::SegmentStream(QObject* parent) : QObject(parent) {}

SegmentStream::~SegmentStream() = default;

int SegmentStream::poseCount() const
{
    return m_state ? int(m_state->animation->poseCount()) : 0;
}

void SegmentStream::start(std::shared_ptr<const MeshAnimation> animation, const SegmenterSettings& settings, double h)
{
    if (animation->restPose != 0)
        throw std::invalid_argument("A pose stream starts at the rest pose, which must be pose 0.");
    abandonTask();
    m_state = std::make_shared<SegmentStreamState>();
    m_state->animation = std::move(animation);
    m_state->settings = settings;
    m_h = h;
    m_processed = 0;
    m_reached = 0;
    m_lastPose = 0;
    startNextStep();
}

void SegmentStream::poseReached(int pose)
{
    if (!m_state)
        return;
    m_reached = pose < m_lastPose ? poseCount() - 1 : std::max(m_reached, pose);
    m_lastPose = pose;
    startNextStep();
}

void SegmentStream::stop()
{
    if (!m_state)
        return;
    abandonTask();
    m_state.reset();
    emit stopped();
}

void SegmentStream::startNextStep()
{
    if (!m_state || (m_task && m_task->isRunning()))
        return;
    if (m_processed == poseCount()) {
        startCompletion();
        return;
    }
    if (m_processed > m_reached)
        return; // wait for the timeline
    prepareTask();
    connect(m_task, &BackgroundTask::succeeded, this, &SegmentStream::onStepSucceeded);
    const std::shared_ptr<SegmentStreamState> state = m_state;
    const auto pose = std::size_t(m_processed);
    const double h = m_h;
    m_task->start([state, pose, h](const TaskControl& control) { appendStreamPose(*state, pose, h, control); });
}

void SegmentStream::onStepSucceeded()
{
    const StreamStep step = m_state->step; // a receiver may stop the stream
    m_processed = step.processed;
    emit stepped(step);
    startNextStep();
}

void SegmentStream::startCompletion()
{
    prepareTask();
    connect(m_task, &BackgroundTask::succeeded, this, [this] {
        std::shared_ptr<const SegmentationResult> result = m_state->result;
        m_state.reset();
        emit finished(std::move(result));
    });
    const std::shared_ptr<SegmentStreamState> state = m_state;
    m_task->start([state](const TaskControl& control) { state->result = completeSegmentation(state->segmenter, control); });
}

// The task for the next job, connected to failed() only; the caller adds the success
// handler of its job.
void SegmentStream::prepareTask()
{
    if (!m_task)
        m_task = new BackgroundTask(this);
    m_task->disconnect(this);
    connect(m_task, &BackgroundTask::failed, this, &SegmentStream::onFailed);
}

void SegmentStream::onFailed(const QString& message)
{
    abandonTask();
    m_state.reset();
    emit failed(message);
}

void SegmentStream::abandonTask()
{
    if (!m_task)
        return;
    BackgroundTask* task = std::exchange(m_task, nullptr);
    task->disconnect(this);
    if (!task->isRunning()) {
        task->deleteLater();
        return;
    }
    connect(task, &BackgroundTask::finished, task, &QObject::deleteLater);
    task->cancel();
}

} // namespace trimlab::ui
