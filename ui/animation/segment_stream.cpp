#include "ui/animation/segment_stream.h"

#include "ui/common/background_job.h"

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
/// cleans with `h` and colors from the previous step; returns the step.
StreamStep appendStreamPose(SegmentStreamState& state, std::size_t pose, double h, const TaskControl& control)
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
    step.colors = step.labeling.labels.empty() ? colorSegments(segmenter.graph(), labeling, segmenter.vertexAreas())
                                               : propagateColors(segmenter.graph(), segmenter.vertexAreas(),
                                                                 step.labeling, step.colors, labeling);
    step.labeling = std::move(labeling);
    step.processed = int(pose) + 1;
    step.times = segmenter.times();
    step.stepMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return step;
}

} // namespace

SegmentStream::SegmentStream(QObject* parent) : QObject(parent)
{
}

SegmentStream::~SegmentStream() = default;

int SegmentStream::poseCount() const
{
    return m_state ? int(m_state->animation->poseCount()) : 0;
}

void SegmentStream::start(std::shared_ptr<const MeshAnimation> animation, const SegmenterSettings& settings, double h)
{
    if (animation->restPose != 0)
        throw std::invalid_argument("A pose stream starts at the rest pose, which must be pose 0.");
    abandonJob();
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
    abandonJob();
    m_state.reset();
    emit stopped();
}

void SegmentStream::startNextStep()
{
    if (!m_state || (m_job && m_job->isRunning()))
        return;
    if (m_processed == poseCount()) {
        startCompletion();
        return;
    }
    if (m_processed > m_reached)
        return; // wait for the timeline
    auto* job = newJob<StreamStep>();
    connect(job, &BackgroundJobBase::succeeded, this, [this, job] { onStepSucceeded(job->takeResult()); });
    const std::shared_ptr<SegmentStreamState> state = m_state;
    const auto pose = std::size_t(m_processed);
    const double h = m_h;
    job->start([state, pose, h](const TaskControl& control) { return appendStreamPose(*state, pose, h, control); });
}

void SegmentStream::onStepSucceeded(const StreamStep& step)
{
    m_processed = step.processed;
    emit stepped(step); // a receiver may stop the stream
    startNextStep();
}

void SegmentStream::startCompletion()
{
    auto* job = newJob<std::shared_ptr<const SegmentationResult>>();
    connect(job, &BackgroundJobBase::succeeded, this, [this, job] {
        std::shared_ptr<const SegmentationResult> result = job->takeResult();
        m_state.reset();
        emit finished(std::move(result));
    });
    const std::shared_ptr<SegmentStreamState> state = m_state;
    job->start([state](const TaskControl& control) { return completeSegmentation(state->segmenter, control); });
}

template <class T>
BackgroundJob<T>* SegmentStream::newJob()
{
    abandonJob();
    auto* job = new BackgroundJob<T>(this);
    connect(job, &BackgroundJobBase::failed, this, &SegmentStream::onFailed);
    m_job = job;
    return job;
}

void SegmentStream::onFailed(const QString& message)
{
    abandonJob();
    m_state.reset();
    emit failed(message);
}

void SegmentStream::abandonJob()
{
    if (m_job)
        std::exchange(m_job, nullptr)->abandon(this);
}

} // namespace trimlab::ui
