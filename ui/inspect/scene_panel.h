#pragma once
/// \file
/// The Scene panel (the content of the main window's "Scene" dock): the objects of the
/// scene shown, each with its id, name, whether the CSG expression shows it and its own
/// rule (the Render panel's rule unless overridden); the transform of the current
/// object (object_transform_form.h); the CSG expression (csg_expression_field.h) with
/// buttons that combine the selected objects; and "Add Object…" (File ▸ Add Object…).
/// Every edit goes to the InspectScene (undoable) and renders at once; the panel only
/// shows what the InspectScene holds. Below them, the window may place the trimmed
/// solid's measures (solid_measures_view.h).
///
/// Transforms cannot be edited while a deformation history is designed on the scene's
/// only object (the brush works in that object's frame) or an animation is shown, or for
/// an object whose model matrix is not a rotation, uniform scale and translation; the
/// panel says why.

#include "core/trim/csg_expression.h"

#include <QWidget>

class QGroupBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace trimlab::ui {

class CsgExpressionField;
class InspectScene;
class ObjectTransformForm;
class SolidMeasuresView;

class ScenePanel : public QWidget {
    Q_OBJECT
public:
    /// `scene` must outlive the panel.
    explicit ScenePanel(InspectScene& scene, QWidget* parent = nullptr);

    /// Whether transforms may be edited now; `reason` says why not (shown in the panel).
    void setTransformsEditable(bool editable, const QString& reason);
    /// The object whose transform the form shows (−1: none).
    [[nodiscard]] int currentObject() const;
    void setCurrentObject(int object);
    /// The ids of the selected table rows, ascending.
    [[nodiscard]] std::vector<int> selectedObjects() const;

    [[nodiscard]] QTableWidget* objectTable() const { return m_table; }
    [[nodiscard]] ObjectTransformForm* transformForm() const { return m_transform; }
    [[nodiscard]] CsgExpressionField* csgField() const { return m_csg; }
    /// Shows `view` (parented to the panel) below the CSG expression.
    void setSolidMeasures(SolidMeasuresView* view);
    [[nodiscard]] SolidMeasuresView* solidMeasures() const { return m_solidMeasures; }

    /// The table's columns.
    enum Column { IdColumn, NameColumn, InCsgColumn, RuleColumn, ColumnCount };

signals:
    /// "Add Object…" was pressed.
    void addObjectRequested();

private:
    QWidget* createObjectsGroup();
    QGroupBox* createTransformGroup();
    void rebuildTable();
    void refreshCsgColumns();
    void refreshTransform();
    void onRuleChosen(int object, int comboIndex);
    void buildExpression(CsgOperation operation);
    /// The operands a build button combines, in order (the difference's first is the one
    /// kept).
    [[nodiscard]] std::vector<int> buildOperands(CsgOperation operation) const;
    void refreshBuildButtons();

    InspectScene& m_scene;
    QTableWidget* m_table = nullptr;
    QPushButton* m_addObject = nullptr;
    QGroupBox* m_transformGroup = nullptr;
    ObjectTransformForm* m_transform = nullptr;
    QLabel* m_transformNote = nullptr;
    CsgExpressionField* m_csg = nullptr;
    SolidMeasuresView* m_solidMeasures = nullptr;
    bool m_transformsEditable = true;
    QString m_transformsReason;
};

} // namespace trimlab::ui
