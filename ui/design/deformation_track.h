#pragma once
/// \file
/// The track of the Deformation timeline dock: frames 0 … N−1 along the width, each set
/// of concurrent disjoint deformations as a band from its reference frame to its last
/// frame, labelled "Set k: <rule>", every reference frame marked with a triangle, and the
/// shown frame as a vertical line. Clicking or dragging on it chooses a frame.

#include "core/timeline/timeline.h"

#include <QList>
#include <QStringList>
#include <QWidget>

#include <vector>

namespace trimlab::ui {

class DeformationTrack : public QWidget {
    Q_OBJECT
public:
    explicit DeformationTrack(QWidget* parent = nullptr);

    /// What to draw: `frameCount` frames (0: nothing), the sets, the shown frame.
    void setHistory(int frameCount, std::vector<timeline::DeformationSet> sets, int shownFrame);
    void setShownFrame(int frame);

    /// The marked reference frames, one per set, in set order (what is drawn).
    [[nodiscard]] QList<int> referenceFrames() const;
    /// The set labels as drawn, e.g. "Set 2: Confluent".
    [[nodiscard]] QStringList setLabels() const;
    /// The frame nearest to x (widget coordinates).
    [[nodiscard]] int frameAt(double x) const;
    /// The x of frame f's tick.
    [[nodiscard]] double frameX(int frame) const;

    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override;

signals:
    void frameClicked(int frame);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    void paintSets(class QPainter& painter) const;
    void paintTicks(QPainter& painter) const;

    int m_frameCount = 0;
    std::vector<timeline::DeformationSet> m_sets;
    int m_shownFrame = 0;
};

} // namespace trimlab::ui
