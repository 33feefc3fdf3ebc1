#include "ui/animation/open_animation_dialog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace trimlab::ui {

OpenAnimationDialog::OpenAnimationDialog(const QString& startDirectory, QWidget* parent)
    : QDialog(parent), m_startDirectory(startDirectory)
{
    setWindowTitle(tr("Open Animation"));
    auto* help = new QLabel(tr("A folder of pose files (.obj, .ply, .off, .stl, optionally .gz), a pattern such as "
                               "<i>dir/mesh_%04d.obj.gz</i> or <i>dir/mesh_*.obj</i>, or a glTF file (.gltf, .glb) "
                               "with an animation."));
    help->setWordWrap(true);
    m_source = new QLineEdit;
    m_source->setObjectName(QStringLiteral("animationSourceEdit"));
    m_source->setMinimumWidth(420);
    auto* folder = new QPushButton(tr("Folder…"));
    auto* gltf = new QPushButton(tr("glTF File…"));
    connect(folder, &QPushButton::clicked, this, &OpenAnimationDialog::browseFolder);
    connect(gltf, &QPushButton::clicked, this, &OpenAnimationDialog::browseGltf);
    connect(m_source, &QLineEdit::textChanged, this, &OpenAnimationDialog::updateOk);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* row = new QHBoxLayout;
    row->addWidget(m_source, 1);
    row->addWidget(folder);
    row->addWidget(gltf);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(help);
    layout->addLayout(row);
    layout->addWidget(m_buttons);
    updateOk();
}

QString OpenAnimationDialog::source() const
{
    return m_source->text().trimmed();
}

QString OpenAnimationDialog::getSource(QWidget* parent, const QString& startDirectory)
{
    OpenAnimationDialog dialog(startDirectory, parent);
    return dialog.exec() == QDialog::Accepted ? dialog.source() : QString();
}

QString OpenAnimationDialog::browseStart() const
{
    const QFileInfo current(source());
    if (current.isDir())
        return current.absoluteFilePath();
    return current.dir().exists() && !source().isEmpty() ? current.absolutePath() : m_startDirectory;
}

void OpenAnimationDialog::browseFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Animation Folder"), browseStart());
    if (!folder.isEmpty())
        m_source->setText(folder);
}

void OpenAnimationDialog::browseGltf()
{
    const QString file = QFileDialog::getOpenFileName(this, tr("glTF Animation"), browseStart(),
                                                      tr("glTF (*.gltf *.glb *.gltf.gz *.glb.gz);;All files (*)"));
    if (!file.isEmpty())
        m_source->setText(file);
}

void OpenAnimationDialog::updateOk()
{
    m_buttons->button(QDialogButtonBox::Open)->setEnabled(!source().isEmpty());
}

} // namespace trimlab::ui
