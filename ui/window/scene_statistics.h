#pragma once
/// \file
/// View ▸ Mesh Statistics: the validation report of every object of the scene shown (what
/// `trimlab info` prints: counts, bounds, components, closedness, manifoldness, genus,
/// volume and every defect count), in a dialog that follows the shown scene while open.

#include "core/catalog/scene_source.h"

#include <QDialog>

#include <memory>

class QTextEdit;

namespace trimlab::ui {

class SceneStatisticsDialog : public QDialog {
    Q_OBJECT
public:
    explicit SceneStatisticsDialog(QWidget* parent = nullptr);

    /// Shows the reports of `scene` (nullptr: "nothing is shown").
    void showScene(const std::shared_ptr<const LoadedScene>& scene);
    [[nodiscard]] QString text() const;

private:
    QTextEdit* m_text = nullptr;
};

} // namespace trimlab::ui
