#pragma once
/// \file
/// Real-time segmentation (thesis 3.2.2) on a stream of poses: it starts from the first
/// pose and appends the next pose (AnimationSegmenter::appendPose) each time the
/// timeline has reached it, one pose at a time, in order, each step on a worker
/// (a BackgroundJob returning the step). A step also cleans the segmentation so far with the current h and
/// carries the colors over from the step before (propagateColors), and hands both to the
/// UI thread as stepped(). The UI thread never touches the stream's segmenter while a
/// step runs; after the last pose the segmenter equals a global run (the core
/// guarantees it) and is handed over with its variable segmentation as finished().
///
/// The poses come from the loaded animation, so the stream runs as fast as playback
/// brings them: when the timeline is ahead, steps follow each other without waiting;
/// when the workers are slower than playback, the stream falls behind and catches up.

#include "core/animation/segmentation_run.h"

#include <QObject>
#include <QString>

#include <memory>

namespace trimlab::ui {

class BackgroundJobBase;
template <class T>
class BackgroundJob;
struct SegmentStreamState;

/// What one step shows: the segmentation of poses 0 … processed−1 for the h of the step.
struct StreamStep {
    VertexLabeling labeling;
    std::vector<WheelColor> colors;
    int processed = 0;
    double stepMs = 0.0;     ///< append + cleaning + coloring, wall clock
    SegmentationTimes times; ///< the segmenter's stages of this append
};

class SegmentStream : public QObject {
    Q_OBJECT
public:
    explicit SegmentStream(QObject* parent = nullptr);
    ~SegmentStream() override;

    /// Starts a stream over `animation` (rest pose 0 required) with `settings`, cleaning
    /// with `h`. The first step (pose 0) starts at once; a running stream is stopped
    /// first (without stopped()). Throws std::invalid_argument for a rest pose other
    /// than 0: the stream's first pose must be the rest pose.
    void start(std::shared_ptr<const MeshAnimation> animation, const SegmenterSettings& settings, double h);
    /// The timeline shows `pose`. Poses up to it become available; a pose before the
    /// last one reported (playback looped) makes every pose available.
    void poseReached(int pose);
    /// The h for the next steps.
    void setH(double h) { m_h = h; }
    /// Stops the stream after the running step (emits stopped() at once); its result is
    /// discarded.
    void stop();

    [[nodiscard]] bool isRunning() const { return m_state != nullptr; }
    [[nodiscard]] int processedPoses() const { return m_processed; }
    [[nodiscard]] int poseCount() const;

signals:
    void stepped(const trimlab::ui::StreamStep& step);
    /// Every pose was appended; `result` holds the stream's segmenter (equal to a global
    /// run on the whole animation) and its variable segmentation.
    void finished(std::shared_ptr<const trimlab::SegmentationResult> result);
    void failed(const QString& message);
    void stopped();

private:
    void startNextStep();
    void onStepSucceeded(const StreamStep& step);
    void startCompletion();
    /// A new job for the next step (the previous one let go), connected to failed().
    template <class T>
    BackgroundJob<T>* newJob();
    void onFailed(const QString& message);
    void abandonJob();

    /// The stream's animation, segmenter and last step, shared with the running step's
    /// job (which alone reads and changes it while it runs); nullptr when idle.
    std::shared_ptr<SegmentStreamState> m_state;
    BackgroundJobBase* m_job = nullptr; ///< the running or last step's job
    double m_h = 0.0;
    int m_processed = 0;
    int m_reached = 0;
    int m_lastPose = 0;
};

} // namespace trimlab::ui
