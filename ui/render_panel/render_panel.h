#pragma once
/// \file
/// The Render panel (the content of the main window's "Render" dock): trim on/off, the
/// static rule (with K for the threshold rules), the classification of a designer session (the static rule alone, or the
/// dynamic rules per set with the static rule classifying the base mesh), the clipping
/// planes (clip_set_editor.h: up to six, e.g. a box), capping and highlighting
/// (inspect_group.h) and the multi-fragment method with its parameters and the GPU
/// memory it needs at the current frame size (method_group.h). The CSG expression and
/// the per-object rules are the Scene panel's (scene_panel.h): renderChoices() leaves
/// trim.csg empty. When the scene is not trimmable
/// the trim controls are disabled and a label says why; the user's choice is kept and
/// applies again to the next trimmable scene.

#include "ui/viewport/memory_estimate.h"
#include "ui/render_panel/render_choices.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace trimlab::ui {

class ClipSetEditor;
class InspectGroup;
class MethodGroup;

class RenderPanel : public QWidget {
    Q_OBJECT
public:
    explicit RenderPanel(QWidget* parent = nullptr);

    /// Shows `choices` without emitting renderChoicesChanged().
    void setRenderChoices(const RenderChoices& choices);
    /// What the user chose (trimEnabled as ticked, even while the scene is not trimmable).
    [[nodiscard]] RenderChoices renderChoices() const;

    /// The current scene: its bounds (for the clip offset sliders, the box preset and the
    /// cap spacing, which is RenderChoices::capSpacingFraction of its radius) and whether the trim
    /// modes apply; `reason` is LoadedScene::trimUnavailableReason().
    void setSceneInfo(const Bounds& bounds, bool trimmable, const QString& reason);
    [[nodiscard]] bool sceneTrimmable() const { return m_trimmable; }
    /// New bounds of the scene shown (an object moved or was scaled): the clip offset
    /// sliders, the box preset and the cap spacing follow them, so the pattern keeps its
    /// look on a scaled object.
    void setClipBounds(const Bounds& bounds);
    /// Shows the chosen method's GPU memory estimate (from the viewport's renderer).
    void setMemoryEstimate(const MemoryEstimate& estimate);
    /// Answers viewDirectionRequested(): clip normal along `viewDirection`, through the
    /// scene centre.
    void setClipNormal(const glm::dvec3& viewDirection);

    [[nodiscard]] ClipSetEditor* clipSetEditor() const { return m_clip; }
    [[nodiscard]] InspectGroup* inspectGroup() const { return m_inspect; }
    [[nodiscard]] MethodGroup* methodGroup() const { return m_methodGroup; }

signals:
    /// Any user edit of the render choices.
    void renderChoicesChanged();
    /// The clip "View" preset was pressed (see setClipNormal).
    void viewDirectionRequested();

private:
    QWidget* createTrimGroup();
    /// The rule of the combo box, K from the spin box for the threshold kinds.
    [[nodiscard]] StaticRule chosenRule() const;
    /// K applies to the threshold kinds only.
    void refreshThresholdEnabled();

    QCheckBox* m_trim = nullptr;
    QComboBox* m_rule = nullptr;
    QSpinBox* m_threshold = nullptr;
    QComboBox* m_classification = nullptr;
    QLabel* m_trimUnavailable = nullptr;
    ClipSetEditor* m_clip = nullptr;
    InspectGroup* m_inspect = nullptr;
    Bounds m_bounds;
    MethodGroup* m_methodGroup = nullptr;
    bool m_trimmable = true;
};

} // namespace trimlab::ui
