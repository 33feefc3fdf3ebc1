#include "ui/inspect/scene_panel.h"

#include "ui/common/rule_labels.h"
#include "ui/inspect/csg_expression_field.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/object_transform_form.h"
#include "ui/inspect/solid_measures_view.h"

#include <QComboBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace trimlab::ui {

namespace {

QTableWidgetItem* readOnlyItem(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    return item;
}

} // namespace

ScenePanel::ScenePanel(InspectScene& scene, QWidget* parent) : QWidget(parent), m_scene(scene)
{
    setObjectName(QStringLiteral("scenePanel"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createObjectsGroup());
    layout->addWidget(createTransformGroup());
    m_csg = new CsgExpressionField(this);
    layout->addWidget(m_csg);
    layout->addStretch();
    connect(m_csg, &CsgExpressionField::expressionTyped, this, [this](const CsgExpression& expression) {
        CsgSettings csg = m_scene.csg();
        csg.expression = expression;
        const QString text = expression.empty()
                                 ? tr("CSG off")
                                 : tr("CSG %1").arg(QString::fromStdString(formatCsgExpression(expression)));
        m_scene.editCsg(csg, text, true);
    });
    connect(m_csg, &CsgExpressionField::typingFinished, this, [this] { m_scene.endTyping(); });
    connect(m_csg, &CsgExpressionField::buildRequested, this, &ScenePanel::buildExpression);
    connect(&m_scene, &InspectScene::sceneReplaced, this, &ScenePanel::rebuildTable);
    connect(&m_scene, &InspectScene::csgChanged, this, &ScenePanel::refreshCsgColumns);
    connect(&m_scene, &InspectScene::transformChanged, this, [this](int object) {
        if (object == currentObject())
            refreshTransform();
    });
    rebuildTable();
}

void ScenePanel::setSolidMeasures(SolidMeasuresView* view)
{
    auto* box = static_cast<QVBoxLayout*>(layout());
    view->setParent(this);
    box->insertWidget(box->count() - 1, view); // above the stretch
    m_solidMeasures = view;
}

QWidget* ScenePanel::createObjectsGroup()
{
    auto* group = new QGroupBox(tr("Objects"), this);
    auto* layout = new QVBoxLayout(group);
    m_table = new QTableWidget(0, ColumnCount, group);
    m_table->setObjectName(QStringLiteral("sceneObjectTable"));
    m_table->setHorizontalHeaderLabels({tr("Id"), tr("Name"), tr("In CSG"), tr("Rule")});
    m_table->horizontalHeaderItem(InCsgColumn)
        ->setToolTip(tr("Whether the CSG expression shows the object (without an expression every object is shown)"));
    m_table->horizontalHeaderItem(RuleColumn)
        ->setToolTip(tr("The rule that classifies the object on its own "
                        "(CSG, collisions); \"Scene rule\" is the Render "
                        "panel's"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(IdColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(InCsgColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(RuleColumn, QHeaderView::ResizeToContents);
    m_table->setMinimumHeight(120);
    layout->addWidget(m_table);
    m_addObject = new QPushButton(tr("Add Object…"), group);
    m_addObject->setObjectName(QStringLiteral("addObjectButton"));
    m_addObject->setToolTip(tr("Load a mesh file into the scene as one more object (File ▸ Add Object…)"));
    connect(m_addObject, &QPushButton::clicked, this, &ScenePanel::addObjectRequested);
    layout->addWidget(m_addObject, 0, Qt::AlignLeft);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this] {
        refreshTransform();
        refreshBuildButtons(); // the difference keeps the current object
    });
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &ScenePanel::refreshBuildButtons);
    return group;
}

QGroupBox* ScenePanel::createTransformGroup()
{
    m_transformGroup = new QGroupBox(tr("Transform"), this);
    m_transformGroup->setObjectName(QStringLiteral("transformGroup"));
    auto* layout = new QVBoxLayout(m_transformGroup);
    m_transform = new ObjectTransformForm(m_transformGroup);
    layout->addWidget(m_transform);
    m_transformNote = new QLabel(m_transformGroup);
    m_transformNote->setObjectName(QStringLiteral("transformNoteLabel"));
    m_transformNote->setWordWrap(true);
    m_transformNote->setVisible(false);
    layout->addWidget(m_transformNote);
    connect(m_transform, &ObjectTransformForm::transformEdited, this,
            [this](const ObjectTransform& transform) { m_scene.editTransform(currentObject(), transform); });
    return m_transformGroup;
}

void ScenePanel::setTransformsEditable(bool editable, const QString& reason)
{
    m_transformsEditable = editable;
    m_transformsReason = reason;
    refreshTransform();
}

int ScenePanel::currentObject() const
{
    const int row = m_table->currentRow();
    return row >= 0 && row < m_scene.objectCount() ? row : -1;
}

void ScenePanel::setCurrentObject(int object)
{
    if (object >= 0 && object < m_table->rowCount())
        m_table->setCurrentCell(object, NameColumn);
}

std::vector<int> ScenePanel::selectedObjects() const
{
    std::vector<int> objects;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
        objects.push_back(index.row());
    std::sort(objects.begin(), objects.end());
    return objects;
}

void ScenePanel::rebuildTable()
{
    const QSignalBlocker blocker(m_table);
    const int previous = m_table->currentRow();
    m_table->clearContents();
    m_table->setRowCount(m_scene.objectCount());
    for (int i = 0; i < m_scene.objectCount(); ++i) {
        const SceneObject& object = m_scene.scene()->scene.objects[std::size_t(i)];
        m_table->setItem(i, IdColumn, readOnlyItem(QString::number(i)));
        m_table->setItem(i, NameColumn, readOnlyItem(QString::fromStdString(object.name)));
        m_table->setItem(i, InCsgColumn, readOnlyItem(QString()));
        auto* rule = new QComboBox(m_table);
        rule->setObjectName(QStringLiteral("objectRuleCombo%1").arg(i));
        rule->addItem(tr("Scene rule"));
        addRuleItems(rule);
        rule->setEnabled(i < kMaxCsgOperands); // per-object classification addresses 8 objects
        connect(rule, &QComboBox::activated, this, [this, i](int index) { onRuleChosen(i, index); });
        m_table->setCellWidget(i, RuleColumn, rule);
    }
    m_csg->setObjectCount(m_scene.objectCount());
    if (m_scene.objectCount() > 0)
        m_table->setCurrentCell(std::clamp(previous, 0, m_scene.objectCount() - 1), NameColumn);
    refreshCsgColumns();
    refreshTransform();
    refreshBuildButtons();
}

void ScenePanel::refreshCsgColumns()
{
    const CsgSettings& csg = m_scene.csg();
    const std::uint32_t shown = csgOperandMask(csg.expression);
    for (int i = 0; i < m_table->rowCount(); ++i) {
        const bool inCsg = !csg.enabled() || (i < 32 && ((shown >> i) & 1u) != 0);
        if (QTableWidgetItem* item = m_table->item(i, InCsgColumn))
            item->setText(inCsg ? QStringLiteral("✓") : QString());
        if (auto* rule = qobject_cast<QComboBox*>(m_table->cellWidget(i, RuleColumn))) {
            const QSignalBlocker blocker(rule);
            const std::optional<StaticRule> chosen =
                i < kMaxCsgOperands ? csg.objectRules[std::size_t(i)] : std::optional<StaticRule>();
            if (chosen)
                selectRule(rule, *chosen);
            else
                rule->setCurrentIndex(0);
        }
    }
    m_csg->setExpression(csg.expression);
}

void ScenePanel::refreshTransform()
{
    const int object = currentObject();
    const std::optional<ObjectTransform> transform = m_scene.transform(object);
    QString note;
    if (object < 0)
        note = tr("Select an object.");
    else if (!m_transformsEditable)
        note = m_transformsReason;
    else if (!transform)
        note = tr("This object's model matrix is not a rotation, uniform scale and translation; it cannot be "
                  "edited here.");
    m_transformGroup->setTitle(
        object < 0 ? tr("Transform")
                   : tr("Transform of object %1 (%2)").arg(object).arg(m_table->item(object, NameColumn)->text()));
    m_transform->setTransform(transform.value_or(ObjectTransform{}));
    m_transform->setEnabled(note.isEmpty());
    m_transformNote->setText(note);
    m_transformNote->setVisible(!note.isEmpty());
    if (m_scene.scene()) {
        const Bounds bounds = m_scene.scene()->scene.worldBounds();
        m_transform->setTranslationStep(bounds.valid() ? std::max(bounds.radius(), 1e-6) / 20.0 : 0.05);
    }
}

void ScenePanel::onRuleChosen(int object, int comboIndex)
{
    if (object < 0 || object >= kMaxCsgOperands)
        return;
    CsgSettings csg = m_scene.csg();
    const auto* combo = qobject_cast<QComboBox*>(m_table->cellWidget(object, RuleColumn));
    const std::optional<StaticRule> rule =
        combo && comboIndex > 0 ? parseStaticRule(combo->itemData(comboIndex).toString().toStdString()) : std::nullopt;
    csg.objectRules[std::size_t(object)] = rule;
    const QString name = rule ? ruleLabel(*rule) : tr("scene rule");
    m_scene.editCsg(csg, tr("Object %1 rule: %2").arg(object).arg(name));
}

// Union and intersection of the selection in id order; the difference keeps the current
// object (when selected, else the lowest id) and removes the others.
std::vector<int> ScenePanel::buildOperands(CsgOperation operation) const
{
    std::vector<int> objects = selectedObjects();
    objects.erase(std::remove_if(objects.begin(), objects.end(), [](int id) { return id >= kMaxCsgOperands; }),
                  objects.end());
    const auto current = std::find(objects.begin(), objects.end(), currentObject());
    if (operation == CsgOperation::Difference && current != objects.end())
        std::rotate(objects.begin(), current, current + 1);
    return objects;
}

void ScenePanel::refreshBuildButtons()
{
    const std::vector<int> difference = buildOperands(CsgOperation::Difference);
    m_csg->setSelection(int(selectedObjects().size()), difference.size() >= 2 ? difference.front() : -1);
}

void ScenePanel::buildExpression(CsgOperation operation)
{
    const std::vector<int> objects = buildOperands(operation);
    if (objects.size() < 2)
        return;
    std::vector<CsgExpression> operands;
    for (const int id : objects)
        operands.push_back(CsgExpression::operand(id));
    CsgSettings csg = m_scene.csg();
    csg.expression = CsgExpression::combine(operation, operands);
    m_scene.editCsg(csg, tr("CSG %1").arg(QString::fromStdString(formatCsgExpression(csg.expression))));
}

} // namespace trimlab::ui
