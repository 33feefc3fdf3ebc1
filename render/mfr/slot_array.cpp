#include "render/mfr/slot_array.h"

#include "render/gl/bindings.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/method_parameter_table.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {
constexpr std::size_t kBytesPerSlot = 8; // RG32UI, fragment_pack.glsl
}

SlotArray::SlotArray(GlFunctions& gl) : m_gl(gl)
{
}

std::size_t SlotArray::slotBytes(int width, int height, int k)
{
    return std::size_t(width) * std::size_t(height) * std::size_t(k) * kBytesPerSlot;
}

void SlotArray::allocate(int width, int height, int k, const char* owner)
{
    requireParameterValue(method_parameters::kK, k);
    if (width == m_width && height == m_height && k == m_k)
        return;
    m_width = m_height = m_k = 0;
    m_texture = GlTexture(m_gl);
    m_gl.glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture.id());
    m_gl.glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RG32UI, width, height, k);
    checkAllocation(m_gl,
                    (std::string(owner) + " (k = " + std::to_string(k) + " at " + std::to_string(width) + "x" +
                     std::to_string(height) + ")")
                        .c_str(),
                    double(slotBytes(width, height, k)));
    m_width = width;
    m_height = height;
    m_k = k;
}

void SlotArray::bind()
{
    m_gl.glBindImageTexture(binding::kFragmentsImage, m_texture.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RG32UI);
}

} // namespace trimlab::render
