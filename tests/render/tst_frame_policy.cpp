// The viewport's frame policy (render/frame_policy.h) without a widget or a context: the
// memory fallback chain it walks, the CPU still and the refusal under the dynamic rules,
// and how GPU resets in a row blame the method or stop the view. The widget that carries
// these decisions out is tested in ui.context_loss and ui.method_panel.
#include "render/frame_policy.h"
#include "render/memory_fallback.h"

#include <QtTest>

#include <string>

using namespace trimlab::render;
using Action = FrameRecovery::Action;

namespace {

const FrameDemands kStatic{};
const FrameDemands kDynamic{true, false};
const FrameDemands kInspection{false, true};

std::string name(FragmentMethodKind method)
{
    return std::string(methodInfo(method).displayName);
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

class TestFramePolicy : public QObject {
    Q_OBJECT
private slots:
    void startsOnTheChosenMethod();
    void outOfMemoryWalksTheFallbackChain_data();
    void outOfMemoryWalksTheFallbackChain();
    void dynamicRulesRefuseWhereTheChainEnds();
    void inspectionSkipsPeeling();
    void resetGoesBackToTheChosenMethod();
    void oneResetRecreatesTheContext();
    void resetsInARowBlameTheMethod();
    void aFrameBetweenResetsBlamesNothing();
    void resetsUnderTheDynamicRulesStopTheView();
    void resetsDuringTheCpuStillBlameNothing();
};

void TestFramePolicy::startsOnTheChosenMethod()
{
    FramePolicy policy;
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::KPlusArray);
    policy.choose(FragmentMethodKind::ABufferLinkedList);
    QCOMPARE(policy.chosenMethod(), FragmentMethodKind::ABufferLinkedList);
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::ABufferLinkedList);
    QVERIFY(!policy.showsCpuStill());
    QVERIFY(!policy.stopped());
}

void TestFramePolicy::outOfMemoryWalksTheFallbackChain_data()
{
    QTest::addColumn<int>("method");
    for (const MethodInfo& info : fragmentMethods())
        QTest::newRow(info.id.data()) << int(info.kind);
}

// Every step is memoryFallbackAfter's, the message names the reason and the method shown
// instead, and the chain ends in the CPU still under the static rule.
void TestFramePolicy::outOfMemoryWalksTheFallbackChain()
{
    QFETCH(int, method);
    FramePolicy policy;
    policy.choose(FragmentMethodKind(method));
    for (int step = 0; step < 8; ++step) {
        const FragmentMethodKind failed = policy.effectiveMethod();
        const std::optional<FragmentMethodKind> expected = memoryFallbackAfter(failed, false, false);
        const FrameRecovery recovery = policy.outOfMemory("Out of memory.", kStatic);
        QVERIFY(contains(recovery.message, "Out of memory."));
        if (!expected) {
            QCOMPARE(recovery.action, Action::CpuStill);
            QVERIFY(policy.showsCpuStill());
            QVERIFY(contains(recovery.message, "showing the CPU reference as a still image"));
            QCOMPARE(policy.chosenMethod(), FragmentMethodKind(method)); // the choice stays
            return;
        }
        QCOMPARE(recovery.action, Action::OtherMethod);
        QCOMPARE(policy.effectiveMethod(), *expected);
        QVERIFY(contains(recovery.message, "Showing " + name(*expected) + " instead"));
    }
    QFAIL("the fallback chain did not end");
}

void TestFramePolicy::dynamicRulesRefuseWhereTheChainEnds()
{
    FramePolicy policy;
    policy.choose(FragmentMethodKind::KPlusArray);
    QCOMPARE(policy.outOfMemory("Too big.", kDynamic).action, Action::OtherMethod);
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::SBuffer);
    const FrameRecovery refused = policy.outOfMemory("Too big.", kDynamic);
    QCOMPARE(refused.action, Action::Refuse);
    QVERIFY(contains(refused.message, "No GPU method with the dynamic rules fits"));
    QVERIFY(!policy.showsCpuStill()); // the CPU still knows only the static rules
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::SBuffer);
}

void TestFramePolicy::inspectionSkipsPeeling()
{
    FramePolicy policy;
    policy.choose(FragmentMethodKind::SBuffer);
    QCOMPARE(policy.outOfMemory("Too big.", kInspection).action, Action::CpuStill);
}

void TestFramePolicy::resetGoesBackToTheChosenMethod()
{
    FramePolicy policy;
    policy.choose(FragmentMethodKind::SBuffer);
    (void)policy.outOfMemory("a", kStatic);
    (void)policy.outOfMemory("b", kStatic);
    QVERIFY(policy.showsCpuStill());
    policy.reset();
    QVERIFY(!policy.showsCpuStill());
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::SBuffer);
}

void TestFramePolicy::oneResetRecreatesTheContext()
{
    FramePolicy policy;
    const FrameRecovery recovery = policy.contextLost("The GPU was reset.", kStatic);
    QCOMPARE(recovery.action, Action::Recreate);
    QVERIFY(contains(recovery.message, "The GPU was reset."));
    QVERIFY(contains(recovery.message, "nothing of your work was lost"));
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::KPlusArray);
}

void TestFramePolicy::resetsInARowBlameTheMethod()
{
    FramePolicy policy;
    QCOMPARE(policy.contextLost("Reset.", kStatic).action, Action::Recreate);
    const FrameRecovery blamed = policy.contextLost("Reset.", kStatic);
    QCOMPARE(blamed.action, Action::OtherMethod);
    QVERIFY(contains(blamed.message, "It happened again while rendering with " + name(FragmentMethodKind::KPlusArray)));
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::SBuffer);
    // The count starts over after the blame.
    QCOMPARE(policy.contextLost("Reset.", kStatic).action, Action::Recreate);
}

void TestFramePolicy::aFrameBetweenResetsBlamesNothing()
{
    FramePolicy policy;
    QCOMPARE(policy.contextLost("Reset.", kStatic).action, Action::Recreate);
    policy.frameRendered();
    QCOMPARE(policy.contextLost("Reset.", kStatic).action, Action::Recreate);
    QCOMPARE(policy.effectiveMethod(), FragmentMethodKind::KPlusArray);
}

void TestFramePolicy::resetsUnderTheDynamicRulesStopTheView()
{
    FramePolicy policy;
    policy.choose(FragmentMethodKind::SBuffer);
    QCOMPARE(policy.contextLost("Reset.", kDynamic).action, Action::Recreate);
    const FrameRecovery stop = policy.contextLost("Reset.", kDynamic);
    QCOMPARE(stop.action, Action::Stop);
    QVERIFY(contains(stop.message, "stopped rendering"));
    QVERIFY(policy.stopped());
    policy.clearStop(); // a new dynamic chain
    QVERIFY(!policy.stopped());
    QCOMPARE(policy.contextLost("Reset.", kDynamic).action, Action::Recreate);
    QCOMPARE(policy.contextLost("Reset.", kDynamic).action, Action::Stop);
    policy.reset(); // another method, size or scene
    QVERIFY(!policy.stopped());
}

void TestFramePolicy::resetsDuringTheCpuStillBlameNothing()
{
    FramePolicy policy;
    policy.choose(FragmentMethodKind::PeelingF2B);
    QCOMPARE(policy.outOfMemory("Too big.", kStatic).action, Action::CpuStill);
    QCOMPARE(policy.contextLost("Reset.", kStatic).action, Action::Recreate);
    QCOMPARE(policy.contextLost("Reset.", kStatic).action, Action::Recreate);
    QVERIFY(policy.showsCpuStill());
}

QTEST_APPLESS_MAIN(TestFramePolicy)
#include "tst_frame_policy.moc"
