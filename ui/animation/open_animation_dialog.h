#pragma once
/// \file
/// File ▸ Open Animation…: asks for what loadAnimation accepts — a folder of pose files,
/// a numbered or wildcard pattern typed by hand (dir/mesh_%04d.obj.gz, dir/mesh_*.obj),
/// or a .gltf/.glb file — with browse buttons for a folder and for a glTF file.

#include <QDialog>
#include <QString>

class QDialogButtonBox;
class QLineEdit;

namespace trimlab::ui {

class OpenAnimationDialog : public QDialog {
    Q_OBJECT
public:
    /// Browsing starts in `startDirectory`.
    OpenAnimationDialog(const QString& startDirectory, QWidget* parent = nullptr);

    /// The source as entered (trimmed); empty when nothing was entered.
    [[nodiscard]] QString source() const;

    /// Shows the dialog modally; the chosen source, or "" when canceled.
    [[nodiscard]] static QString getSource(QWidget* parent, const QString& startDirectory);

private:
    void browseFolder();
    void browseGltf();
    void updateOk();
    [[nodiscard]] QString browseStart() const;

    QString m_startDirectory;
    QLineEdit* m_source = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

} // namespace trimlab::ui
