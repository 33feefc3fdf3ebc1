#include "ui/skinning/skinning_session.h"

#include "ui/skinning/skinning_edit_command.h"

namespace trimlab::ui {

SkinningSession::SkinningSession(std::shared_ptr<const SkinningFit> fit, QObject* parent)
    : QObject(parent), m_fit(std::move(fit))
{
    m_fitted = std::shared_ptr<const SkinningModel>(m_fit, &m_fit->result.model);
    setModel(m_fitted);
}

std::vector<glm::vec3> SkinningSession::approximatePose(std::size_t pose) const
{
    const PosePositions& positions = m_approximation->at(pose);
    return {positions.begin(), positions.end()};
}

void SkinningSession::editBone(std::size_t pose, std::size_t bone, const BoneEdit& edit)
{
    auto edited =
        std::make_shared<const SkinningModel>(applyBoneEdit(*m_model, pose, bone, edit, approximation()[pose]));
    m_undo.push(
        new SkinningEditCommand(this, m_model, std::move(edited), tr("Move bone %1 at pose %2").arg(bone).arg(pose)));
}

void SkinningSession::setModel(std::shared_ptr<const SkinningModel> model)
{
    m_model = std::move(model);
    if (m_model == m_fitted) {
        // The fit's own reconstruction and error: undoing every edit gives them back exactly.
        m_approximation = std::shared_ptr<const std::vector<PosePositions>>(m_fit, &m_fit->approximation);
        m_error = std::shared_ptr<const SkinningError>(m_fit, &m_fit->result.error);
    } else {
        auto approximation = std::make_shared<const std::vector<PosePositions>>(reconstructPoses(*m_model));
        m_error = std::make_shared<const SkinningError>(
            measureSkinningError(m_fit->original, *approximation, m_model->restPose));
        m_approximation = std::move(approximation);
    }
    emit modelChanged();
}

} // namespace trimlab::ui
