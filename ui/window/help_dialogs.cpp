#include "ui/window/help_dialogs.h"

#include "ui/viewport/viewport_widget.h"

#include "ui/common/frame_slider.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace trimlab::ui {

namespace {

struct ShortcutRow {
    QString menu;
    QString action;
    QString keys;
};

QString plainText(QString text)
{
    return text.remove(QLatin1Char('&'));
}

// Depth first through `menu` and its submenus, `path` naming where it sits.
void collectShortcuts(const QMenu& menu, const QString& path, std::vector<ShortcutRow>& rows)
{
    for (QAction* action : menu.actions()) {
        if (QMenu* sub = action->menu()) {
            collectShortcuts(*sub, path + QStringLiteral(" ▸ ") + plainText(sub->title()), rows);
            continue;
        }
        if (!action->shortcut().isEmpty())
            rows.push_back({path, plainText(action->text()), action->shortcut().toString(QKeySequence::NativeText)});
    }
}

QDialog* closableDialog(QWidget* parent, const QString& title, const QString& objectName)
{
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(objectName);
    dialog->setWindowTitle(title);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    return dialog;
}

void addCloseButton(QDialog& dialog, QVBoxLayout& layout)
{
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    layout.addWidget(buttons);
}

} // namespace

void showKeyboardShortcuts(QMainWindow& window)
{
    std::vector<ShortcutRow> rows;
    for (QAction* action : window.menuBar()->actions())
        if (QMenu* menu = action->menu())
            collectShortcuts(*menu, plainText(menu->title()), rows);
    QDialog* dialog = closableDialog(&window, QObject::tr("Keyboard Shortcuts"), QStringLiteral("shortcutsDialog"));
    auto* layout = new QVBoxLayout(dialog);
    auto* table = new QTableWidget(int(rows.size()), 3, dialog);
    table->setObjectName(QStringLiteral("shortcutsTable"));
    table->setHorizontalHeaderLabels({QObject::tr("Menu"), QObject::tr("Action"), QObject::tr("Keys")});
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->verticalHeader()->hide();
    for (std::size_t r = 0; r < rows.size(); ++r) {
        table->setItem(int(r), 0, new QTableWidgetItem(rows[r].menu));
        table->setItem(int(r), 1, new QTableWidgetItem(rows[r].action));
        table->setItem(int(r), 2, new QTableWidgetItem(rows[r].keys));
    }
    table->resizeColumnsToContents();
    table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(table);
    auto* mouse = new QLabel(QObject::tr("<b>In the view</b> (keys act while the view has the focus): %1")
                                 .arg(ViewportWidget::cameraHelp().toHtmlEscaped()),
                             dialog);
    mouse->setWordWrap(true);
    layout->addWidget(mouse);
    auto* timelines = new QLabel(QObject::tr("<b>On a timeline's slider</b> (Timeline, Deformation timeline): %1")
                                     .arg(FrameSlider::inputHelp().toHtmlEscaped()),
                                 dialog);
    timelines->setObjectName(QStringLiteral("timelineKeysLabel"));
    timelines->setWordWrap(true);
    layout->addWidget(timelines);
    addCloseButton(*dialog, *layout);
    dialog->resize(640, 520);
    dialog->show();
}

void showUserGuide(QWidget* parent)
{
    QDialog* dialog = closableDialog(parent, QObject::tr("TrimLab User Guide"), QStringLiteral("userGuideDialog"));
    auto* layout = new QVBoxLayout(dialog);
    auto* text = new QTextBrowser(dialog);
    text->setObjectName(QStringLiteral("userGuideText"));
    text->setHtml(QObject::tr(
        "<h2>TrimLab in five minutes</h2>"
        "<p>TrimLab shows surfaces that pass through themselves as the solid they enclose: every pixel's surface "
        "layers are counted (the winding number) and a <b>rule</b> decides which count is inside.</p>"
        "<h3>Look at a surface</h3>"
        "<ul><li><b>File ▸ Open</b> a mesh (OBJ, PLY, STL, OFF, glTF), a NURBS file or a project, or drop it on "
        "the window; <b>File ▸ Open Demo</b> has ready-made self-crossing shapes.</li>"
        "<li>Left drag orbits, right drag pans, the wheel zooms; <b>F</b> fits the view, the <b>View</b> menu has "
        "front, top and side views.</li>"
        "<li>The <b>Render</b> panel picks the rule (parity, positive index, alternating border), clipping planes "
        "with capped cuts, highlighting and X-ray, and the multi-fragment method. The <b>Frame statistics</b> tab "
        "says what a frame cost and whether pixels overflowed.</li></ul>"
        "<h3>Deform it</h3>"
        "<ul><li>Press <b>B</b> for the brush and drag on the surface (Shift: along the normal). Every stroke is a "
        "frame of the <b>Deformation timeline</b>; Ctrl+Z undoes it.</li>"
        "<li><b>New set</b> (N) starts a set with its own <b>dynamic rule</b> (constructive, confluent, homogeneous "
        "confluent); choose <i>Dynamic rules</i> under Classification to trim by the history.</li>"
        "<li><b>Create</b> makes NURBS and subdivision surfaces edited through their control points.</li>"
        "<li><b>File ▸ Save Project</b> keeps the history; exports write frames as meshes or glTF.</li></ul>"
        "<h3>Inspect several objects</h3>"
        "<p><b>File ▸ Add Object</b> loads more meshes; the <b>Scene</b> panel combines them with CSG (union, "
        "intersection, difference) and highlights collisions. <b>File ▸ Save Project</b> keeps the scene: every "
        "object where you placed it, the CSG and the rules.</p>"
        "<h3>Animations</h3>"
        "<p><b>File ▸ Open Animation</b> takes a folder of pose meshes or a glTF animation. The <b>Segmentation</b> "
        "panel finds the rigid parts, <b>Skinning</b> fits bones and exports a skinned glTF, and <b>Skeleton</b> "
        "extracts a skeleton of a mesh by contraction.</p>"
        "<h3>Going further</h3>"
        "<p>The documents in the <tt>docs/</tt> folder of TrimLab's sources: designer-workflow.md (the brush and "
        "sets), dynamic-rules.md, xray.md, skinning.md, skeleton-panel.md, file-formats.md and project-format.md. "
        "<b>Help ▸ Keyboard Shortcuts</b> lists every key.</p>"));
    layout->addWidget(text);
    addCloseButton(*dialog, *layout);
    dialog->resize(640, 560);
    dialog->show();
}

} // namespace trimlab::ui
