#pragma once
/// \file
/// The Skeleton panel's parameter form: one group per stage of skeleton extraction by
/// mesh contraction (Berenguer & Moreno III.A–E), the selection first (what a user sets on
/// every mesh) and the solver's stages folded under a "Solver settings" toggle, closed at
/// first — contraction (W_L⁰, s_L, the caps of W_L
/// and W_H, iterations, ordering AMD/COLAMD/METIS, solver CHOLMOD/LDLT), simplification
/// (δ, w_a, w_b), refinement (on/off), selection (target nodes, root joint automatic or
/// an index), weights (c) — and the skinning used for posing (LBS/DQS). Every control
/// takes its range, default and tooltip from its row of core/skeleton/skeleton_parameters.h
/// and has an object name for tests; changed() follows every edit, nodesOrRootChanged()
/// too when only the selection's node count or root changed.

#include "ui/skeleton/skeleton_choices.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace trimlab::ui {

class SkeletonSettingsForm : public QWidget {
    Q_OBJECT
public:
    explicit SkeletonSettingsForm(QWidget* parent = nullptr);

    void setChoices(const SkeletonChoices& choices); ///< emits nothing
    [[nodiscard]] SkeletonChoices choices() const;
    /// Picks the root joint (−1: automatic), as an edit of the root box (signals follow).
    void pickRootJoint(int joint);

signals:
    void changed();
    void nodesOrRootChanged();
    void skinningChanged();

private:
    QWidget* createContractionGroup();
    QWidget* createSimplificationGroup();
    QWidget* createSelectionGroup();
    QWidget* createSolverSection();

    QDoubleSpinBox* m_initialWeight = nullptr;
    QDoubleSpinBox* m_growth = nullptr;
    QDoubleSpinBox* m_maxContraction = nullptr;
    QDoubleSpinBox* m_maxAttraction = nullptr;
    QSpinBox* m_iterations = nullptr;
    QComboBox* m_ordering = nullptr;
    QComboBox* m_solver = nullptr;
    QDoubleSpinBox* m_delta = nullptr;
    QDoubleSpinBox* m_shapeWeight = nullptr;
    QDoubleSpinBox* m_samplingWeight = nullptr;
    QCheckBox* m_refine = nullptr;
    QSpinBox* m_nodes = nullptr;
    QSpinBox* m_root = nullptr;
    QDoubleSpinBox* m_heat = nullptr;
    QComboBox* m_skinning = nullptr;
};

} // namespace trimlab::ui
