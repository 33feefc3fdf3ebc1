// CSG settings against a scene's object count: the expression's largest id first, then
// the object rules, and the reason both front ends print.
#include "core/trim/csg_object_ids.h"

#include "core/trim/csg_expression.h"

#include <QtTest>

using namespace trimlab;

namespace {

CsgSettings withExpression(const char* text)
{
    std::string error;
    CsgSettings csg;
    csg.expression = *parseCsgExpression(text, &error);
    return csg;
}

} // namespace

class TestCsgObjectIds : public QObject {
    Q_OBJECT

private slots:
    void idsInsideTheSceneFit()
    {
        CsgSettings csg = withExpression("0 - (1 | 2)");
        csg.objectRules[2] = StaticRule::Parity;
        QVERIFY(!csgObjectIdOutsideScene(csg, 3));
        QVERIFY(!csgObjectIdOutsideScene(CsgSettings{}, 1));
    }

    void theExpressionsLargestIdComesFirst()
    {
        CsgSettings csg = withExpression("3 & 0 | 4");
        csg.objectRules[2] = StaticRule::Nonzero;
        const auto problem = csgObjectIdOutsideScene(csg, 2);
        QVERIFY(problem && problem->inExpression);
        QCOMPARE(problem->id, 4);
    }

    void thenTheObjectRules()
    {
        CsgSettings csg = withExpression("0 - 1");
        csg.objectRules[5] = StaticRule::Parity;
        csg.objectRules[3] = StaticRule::Parity;
        const auto problem = csgObjectIdOutsideScene(csg, 2);
        QVERIFY(problem && !problem->inExpression);
        QCOMPARE(problem->id, 3);
    }

    void theReasonNamesTheIdAndTheRange()
    {
        QCOMPARE(csgObjectIdReason(1, 1),
                 std::string("refers to object 1, but the scene has 1 object(s) (ids 0 to 0)"));
    }
};

QTEST_APPLESS_MAIN(TestCsgObjectIds)
#include "tst_csg_object_ids.moc"
