#pragma once
/// \file
/// The rig drawn over the 3D view: a transparent child widget of the ViewportWidget that
/// paints, with QPainter over the GL frame, every bone as a line from head to tail and
/// every joint as a dot, the selected bone thicker and in a highlight colour, the root
/// joint as a ring. Joints are projected with the viewport's current camera
/// (ui/viewport/widget_projection.h) and repainted after every frame the viewport renders, so the
/// overlay follows orbit, pan and zoom. It takes no mouse events (skeleton_pose_tool.h
/// does the picking).

#include "ui/viewport/viewport_overlay.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <vector>

namespace trimlab::ui {

class ViewportWidget;

class SkeletonOverlay : public ViewportOverlay {
    Q_OBJECT
public:
    /// Becomes a child of `viewport`, covering it, and follows its size and frames.
    explicit SkeletonOverlay(ViewportWidget* viewport);

    /// Joints in object space of the scene's object 0 (#J), transformed by `model` into
    /// world space; bones as {head, tail} joint pairs; `root` ringed. Empty: nothing drawn.
    void setSkeleton(std::vector<glm::dvec3> joints, std::vector<std::array<int, 2>> bones, int root,
                     const glm::dmat4& model);
    /// The highlighted bone (−1: none).
    void setSelectedBone(int bone);
    [[nodiscard]] int selectedBone() const { return m_selected; }
    [[nodiscard]] const std::vector<std::array<int, 2>>& bones() const { return m_bones; }

    /// The joints in logical widget coordinates with the viewport's current camera
    /// (nullopt: behind the eye).
    [[nodiscard]] std::vector<std::optional<QPointF>> projectedJoints() const;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<glm::dvec3> m_joints; ///< world space
    std::vector<std::array<int, 2>> m_bones;
    int m_root = -1;
    int m_selected = -1;
};

} // namespace trimlab::ui
