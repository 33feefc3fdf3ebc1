#include "render/content_publisher.h"

namespace trimlab::render {

ContentPublisher::ContentPublisher(std::shared_ptr<ShownContent> content, ContentOwner owner)
    : m_content(std::move(content)), m_owner(owner)
{
}

void ContentPublisher::showPose(std::vector<glm::vec3> positions)
{
    if (m_content)
        m_content->publishPose(m_owner, ShownPose{std::move(positions), {}});
}

void ContentPublisher::showSkinnedPose(std::shared_ptr<const SkinningModel> model, std::size_t pose,
                                       std::vector<glm::vec3> positions)
{
    if (m_content)
        m_content->publishPose(m_owner, ShownPose{std::move(positions), SkinnedPose{std::move(model), pose}});
}

void ContentPublisher::showSubdivisionPose(std::shared_ptr<const SubdivisionStencils> stencils,
                                           std::vector<glm::dvec3> controlPoints, std::vector<glm::vec3> positions)
{
    if (m_content)
        m_content->publishPose(
            m_owner, ShownPose{std::move(positions), SubdivisionPose{std::move(stencils), std::move(controlPoints)}});
}

void ContentPublisher::withdrawPose()
{
    if (m_content)
        m_content->withdrawPose(m_owner);
}

bool ContentPublisher::showsPose() const
{
    return m_content && m_owner != ContentOwner::None && m_content->poseOwner() == m_owner;
}

void ContentPublisher::showColors(std::vector<std::uint32_t> rgba8)
{
    if (!m_content)
        return;
    if (rgba8.empty())
        m_content->withdrawColors(m_owner);
    else
        m_content->publishColors(m_owner, std::move(rgba8));
}

bool ContentPublisher::showsColors() const
{
    return m_content && m_owner != ContentOwner::None && m_content->colorOwner() == m_owner;
}

void ContentPublisher::showChain(std::shared_ptr<const DynamicChain> chain)
{
    if (!m_content)
        return;
    if (chain)
        m_content->publishChain(m_owner, std::move(chain));
    else
        m_content->withdrawChain(m_owner);
}

void ContentPublisher::replaceShownLevel(std::shared_ptr<const DynamicChainLevel> level)
{
    if (m_content)
        m_content->replaceShownLevel(m_owner, std::move(level));
}

void ContentPublisher::appendLevel(std::shared_ptr<const DynamicChainLevel> level)
{
    if (m_content)
        m_content->appendLevel(m_owner, std::move(level));
}

bool ContentPublisher::showsChain() const
{
    return m_content && m_owner != ContentOwner::None && m_content->chainOwner() == m_owner;
}

} // namespace trimlab::render
