#pragma once
/// \file
/// View ▸ Mesh Statistics: the validation report of every object as the view shows it
/// (what `trimlab info` prints: counts, bounds, components, closedness, manifoldness,
/// genus, volume and every defect count), in a dialog that follows what is shown while it
/// is open. What is shown is the shown content's posed scene (render/shown_content.h): a
/// design history's frame, a skeleton or animation pose — not the rest mesh the file
/// holds, whose report is kept for objects the view shows unchanged.

#include "render/shown_content.h"

#include "core/catalog/scene_source.h"

#include <QDialog>
#include <QString>

#include <memory>

class QTextEdit;
class QTimer;

namespace trimlab::ui {

class SceneStatisticsDialog : public QDialog {
    Q_OBJECT
public:
    /// Reports what `content` shows; follows its changes while visible.
    explicit SceneStatisticsDialog(std::shared_ptr<const render::ShownContent> content, QWidget* parent = nullptr);

    /// The document shown (its name and its meshes' reports; nullptr: "nothing is shown").
    void showScene(const std::shared_ptr<const LoadedScene>& scene);
    [[nodiscard]] QString text() const;

private:
    void refresh();

    std::shared_ptr<const render::ShownContent> m_content;
    render::ContentSubscription m_follow;
    QTimer* m_refresh = nullptr; ///< one report per burst of changes (playback, drags)
    std::shared_ptr<const LoadedScene> m_scene;
    QTextEdit* m_text = nullptr;
};

/// The report text of `shown` (the objects as the view shows them) for the document
/// `loaded`: an object whose positions are the file's keeps the file's report, one shown
/// otherwise (posed, a frame of a history) is validated as shown.
[[nodiscard]] QString shownSceneReport(const LoadedScene& loaded, const Scene& shown);

} // namespace trimlab::ui
