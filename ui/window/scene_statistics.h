#pragma once
/// \file
/// View ▸ Mesh Statistics: the validation report of every object as the view shows it
/// (what `trimlab info` prints: counts, bounds, components, closedness, manifoldness,
/// genus, volume and every defect count), in a dialog that follows what is shown while it
/// is open. What is shown is the shown content's posed scene (render/shown_content.h): a
/// design history's frame, a skeleton or animation pose — not the rest mesh the file
/// holds, whose report is kept for objects the view shows unchanged.
///
/// Below the report, Measure computes off the UI thread (with Cancel) what a report of
/// counts cannot say: the trimmed solid's volume, surface area and cross-section in each
/// enabled clipping plane (core/solid/solid_measures.h, on the exact export of what is
/// shown), and how often each object crosses itself (self_intersections.h). A change of
/// what is shown cancels a measurement and clears its result: it measured another frame.

#include "render/shown_content.h"
#include "ui/inspect/solid_export.h"

#include "core/solid/self_intersections.h"
#include "core/solid/solid_measures.h"

#include "core/catalog/scene_source.h"

#include <QDialog>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTextEdit;
class QTimer;

namespace trimlab::ui {

template <class T>
class BackgroundJob;

/// What Measure found: the solid's measures (nullopt with the reason when the view shows
/// no solid) and each object's self-intersections.
struct SceneMeasures {
    std::optional<SolidMeasures> solid;
    QString noSolid;       ///< why there is no solid (refusal and remedy)
    TrimSettings settings; ///< the rule or CSG measured
    std::vector<QString> objectNames;
    std::vector<SelfIntersections> crossings; ///< per object
};

/// The measures of what `shown` shows (the solid, when it has one, and every object's
/// self-intersections), for a worker thread. Throws OperationCancelled.
[[nodiscard]] SceneMeasures measureShown(const SolidExport::Shown& shown, const TaskControl& control);
/// The text Mesh Statistics shows for `measures`.
[[nodiscard]] QString sceneMeasuresText(const SceneMeasures& measures);

class SceneStatisticsDialog : public QDialog {
    Q_OBJECT
public:
    /// Reports what `content` shows; follows its changes while visible.
    /// `shownSolid` says what Measure measures (the window's File ▸ Export Trimmed Solid
    /// source: the frame shown with its rule or CSG, or why it shows no solid).
    SceneStatisticsDialog(std::shared_ptr<const render::ShownContent> content, SolidExport::ShownSource shownSolid,
                          QWidget* parent = nullptr);
    ~SceneStatisticsDialog() override;

    /// The document shown (its name and its meshes' reports; nullptr: "nothing is shown").
    void showScene(const std::shared_ptr<const LoadedScene>& scene);
    [[nodiscard]] QString text() const;
    /// The measurement's text ("" before Measure, a hint after a change).
    [[nodiscard]] QString measuresText() const;
    [[nodiscard]] bool isMeasuring() const;

    /// Starts measuring what is shown (the Measure button).
    void measure();

signals:
    /// A measurement ended (succeeded, failed or canceled).
    void measured();

private:
    void refresh();
    void forgetMeasures();
    void showMeasuring(bool running);

    std::shared_ptr<const render::ShownContent> m_content;
    render::ContentSubscription m_follow;
    QTimer* m_refresh = nullptr; ///< one report per burst of changes (playback, drags)
    std::shared_ptr<const LoadedScene> m_scene;
    QTextEdit* m_text = nullptr;
    SolidExport::ShownSource m_shownSolid;
    BackgroundJob<SceneMeasures>* m_job = nullptr;
    QPushButton* m_measure = nullptr;
    QPushButton* m_cancel = nullptr;
    QLabel* m_measures = nullptr;
};

/// The report text of `shown` (the objects as the view shows them) for the document
/// `loaded`: an object whose positions are the file's keeps the file's report, one shown
/// otherwise (posed, a frame of a history) is validated as shown.
[[nodiscard]] QString shownSceneReport(const LoadedScene& loaded, const Scene& shown);

} // namespace trimlab::ui
