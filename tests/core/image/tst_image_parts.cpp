// Colours packed for the GPU: red in the lowest byte, clamped and rounded, opaque.
#include "core/image/packed_rgba8.h"

#include <QtTest>

using namespace trimlab;

class TestImageParts : public QObject {
    Q_OBJECT

private slots:
    void packedColoursPutRedInTheLowestByte()
    {
        QCOMPARE(packRgba8(glm::vec3(1.0f, 0.0f, 0.0f)), 0xFF0000FFu);
        QCOMPARE(packRgba8(glm::vec3(0.0f, 1.0f, 0.0f)), 0xFF00FF00u);
        QCOMPARE(packRgba8(glm::vec3(0.0f, 0.0f, 1.0f)), 0xFFFF0000u);
        QCOMPARE(packRgba8(glm::vec3(0.0f)), 0xFF000000u);
    }

    void packedColoursClampAndRound()
    {
        QCOMPARE(packRgba8(glm::vec3(-1.0f, 2.0f, 0.5f)), 0xFF80FF00u); // 0.5·255 = 127.5 → 128
        QCOMPARE(packRgba8(glm::vec3(0.6f)), 0xFF999999u);              // 153
        QCOMPARE(packRgba8(glm::vec3(1.0f / 255.0f, 0.49f / 255.0f, 0.0f)), 0xFF000001u);
    }
};

QTEST_APPLESS_MAIN(TestImageParts)
#include "tst_image_parts.moc"
