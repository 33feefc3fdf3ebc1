// The driver's and the user's limits checked before a frame allocates anything: texture
// sides, array layers for the slot methods, and the GPU memory budget (no context needed).
#include "render/frame_limits.h"

#include "render/gl/gl_error.h"

#include <QtTest>

#include <functional>
#include <string>

using namespace trimlab;
using namespace trimlab::render;

namespace {

std::string limitError(const std::function<void()>& check)
{
    try {
        check();
    } catch (const GpuMemoryError& e) {
        return e.what();
    }
    return "";
}

GlCapabilities driver()
{
    GlCapabilities capabilities;
    capabilities.maxTextureSize = 4096;
    capabilities.maxArrayTextureLayers = 64;
    return capabilities;
}

} // namespace

class TestFrameLimits : public QObject {
    Q_OBJECT

private slots:
    void framesWithinTheLimitsPass()
    {
        MethodParameters parameters;
        parameters.k = 64;
        checkFrameLimits(FragmentMethodKind::KPlusArray, driver(), parameters, std::size_t(1) << 30, 4096, 4096);
        checkFrameLimits(FragmentMethodKind::SBuffer, GlCapabilities{}, parameters, std::nullopt, 100000, 100000);
    }

    void texturesLargerThanTheDriverAllowsAreRefused()
    {
        const std::string message =
            limitError([] { checkFrameLimits(FragmentMethodKind::SBuffer, driver(), {}, std::nullopt, 5000, 100); });
        QVERIFY2(message.find("5000x100 frame is larger than this driver's 4096 pixel limit") != std::string::npos,
                 message.c_str());
        QVERIFY(message.find("Render a smaller image") != std::string::npos);
    }

    // k counts against the array layers only for the methods that use k.
    void slotMethodsNeedALayerPerSlot()
    {
        MethodParameters parameters;
        parameters.k = 65;
        const std::string message = limitError(
            [&] { checkFrameLimits(FragmentMethodKind::KPlusArray, driver(), parameters, std::nullopt, 64, 64); });
        QVERIFY2(message.find("k = 65") != std::string::npos && message.find("Lower k") != std::string::npos,
                 message.c_str());
        checkFrameLimits(FragmentMethodKind::ABufferLinkedList, driver(), parameters, std::nullopt, 64, 64);
    }

    // The budget applies to a known estimate only; 0 is no budget.
    void theMemoryBudgetBoundsTheEstimate()
    {
        MethodParameters parameters;
        parameters.memoryBudgetBytes = 1000;
        const std::string message = limitError(
            [&] { checkFrameLimits(FragmentMethodKind::SBuffer, driver(), parameters, std::size_t(1001), 8, 8); });
        QVERIFY2(message.find("above the GPU memory budget") != std::string::npos, message.c_str());
        checkFrameLimits(FragmentMethodKind::SBuffer, driver(), parameters, std::size_t(1000), 8, 8);
        checkFrameLimits(FragmentMethodKind::SBuffer, driver(), parameters, std::nullopt, 8, 8);
        parameters.memoryBudgetBytes = 0;
        checkFrameLimits(FragmentMethodKind::SBuffer, driver(), parameters, std::size_t(1) << 40, 8, 8);
    }
};

QTEST_APPLESS_MAIN(TestFrameLimits)
#include "tst_frame_limits.moc"
