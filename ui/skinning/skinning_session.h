#pragma once
/// \file
/// The skinned approximation the Skinning panel shows and edits: a finished fit
/// (core/skinning/skinning_pipeline.h), the model as edited so far, its reconstruction of
/// every pose and its error against the original animation, and the undo stack of the
/// edits. Every edit
/// is a SkinningEditCommand on undoStack(): it swaps whole models (shared, immutable), so
/// undo gives back the previous model exactly — the fitted one after the last undo.
///
/// After a model change the session reconstructs every pose and measures E_RMS on the UI
/// thread: both are linear in #P·#V (about 60 ms together, measured, for a 42k-vertex,
/// 48-pose LBS model with 4 influences per vertex), far below the fit itself, which runs
/// on a worker.

#include "core/skinning/bone_edit.h"
#include "core/skinning/skinning_pipeline.h"

#include "core/skinning/skinning_error.h"

#include <QObject>
#include <QUndoStack>

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace trimlab::ui {

class SkinningSession : public QObject {
    Q_OBJECT
public:
    /// Starts at the fitted model of `fit` (not null) with an empty undo stack.
    explicit SkinningSession(std::shared_ptr<const SkinningFit> fit, QObject* parent = nullptr);

    [[nodiscard]] const SkinningFit& fit() const { return *m_fit; }
    [[nodiscard]] const std::shared_ptr<const SkinningFit>& sharedFit() const { return m_fit; }
    /// The model shown now: the fitted one, or the last edit.
    [[nodiscard]] const std::shared_ptr<const SkinningModel>& model() const { return m_model; }
    [[nodiscard]] bool isEdited() const { return m_model != m_fitted; }
    /// #P × #V reconstruction of model().
    [[nodiscard]] const std::vector<PosePositions>& approximation() const { return *m_approximation; }
    /// Pose `pose` of the approximation in single precision, for the viewport.
    [[nodiscard]] std::vector<glm::vec3> approximatePose(std::size_t pose) const;
    /// model() against the original animation.
    [[nodiscard]] const SkinningError& error() const { return *m_error; }
    [[nodiscard]] QUndoStack* undoStack() { return &m_undo; }

    /// Pushes the edit of bone `bone` at pose `pose` (applyBoneEdit on model()) as an
    /// undoable command. Throws std::invalid_argument as applyBoneEdit does (nothing is
    /// pushed then).
    void editBone(std::size_t pose, std::size_t bone, const BoneEdit& edit);
    /// Shows `model` (a model of this fit's animation); for SkinningEditCommand.
    void setModel(std::shared_ptr<const SkinningModel> model);

signals:
    /// model(), approximation() and error() changed.
    void modelChanged();

private:
    std::shared_ptr<const SkinningFit> m_fit;
    std::shared_ptr<const SkinningModel> m_fitted; ///< aliases m_fit->result.model
    std::shared_ptr<const SkinningModel> m_model;
    std::shared_ptr<const std::vector<PosePositions>> m_approximation;
    std::shared_ptr<const SkinningError> m_error;
    QUndoStack m_undo;
};

} // namespace trimlab::ui
