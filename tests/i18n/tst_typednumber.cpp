// Numbers typed and shown in the UI language's format (core/i18n/TypedNumber): German takes "12,5"
// and a pasted "12.5", shows "12,5"; no language reads a thousands separator; bad text is no number.
#include "TypedNumber.h"

#include <QLocale>
#include <QTest>

using namespace sortie::i18n;

class TestTypedNumber : public QObject
{
    Q_OBJECT

private slots:
    void cleanup() { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); }

    void english()
    {
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        QCOMPARE(parseTypedNumber(QStringLiteral("12.5")), std::optional<double>(12.5));
        QCOMPARE(parseTypedNumber(QStringLiteral(" -3 ")), std::optional<double>(-3));
        QCOMPARE(parseTypedNumber(QStringLiteral("12,5")), std::nullopt);      // a group separator
        QCOMPARE(parseTypedNumber(QStringLiteral("1,500")), std::nullopt);
        QCOMPARE(formatTypedNumber(12.5, 1), QStringLiteral("12.5"));
        QCOMPARE(formatTypedNumber(1500, 0), QStringLiteral("1500"));
        QCOMPARE(formatTypedNumber(56.9765, -1), QStringLiteral("56.9765"));
    }

    void german()
    {
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        QCOMPARE(parseTypedNumber(QStringLiteral("12,5")), std::optional<double>(12.5));
        QCOMPARE(parseTypedNumber(QStringLiteral("12.5")), std::optional<double>(12.5)); // pasted, or on habit
        QCOMPARE(parseTypedNumber(QStringLiteral("1.500")), std::optional<double>(1.5)); // never fifteen hundred
        QCOMPARE(parseTypedNumber(QStringLiteral("1.500,5")), std::nullopt);
        QCOMPARE(formatTypedNumber(12.5, 1), QStringLiteral("12,5"));
        QCOMPARE(formatTypedNumber(1500.25, 2), QStringLiteral("1500,25"));
        QCOMPARE(formatTypedNumber(0.1, -1), QStringLiteral("0,1"));
        QCOMPARE(parseTypedNumber(formatTypedNumber(2.0 / 3.0)), std::optional<double>(2.0 / 3.0)); // reads back
    }

    void notANumber()
    {
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        for (const char *text : {"", "   ", "abc", "12 m", "1,2,3", "--1", "12,5x"})
            QVERIFY2(!parseTypedNumber(QString::fromLatin1(text)), text);
    }
};

QTEST_GUILESS_MAIN(TestTypedNumber)
#include "tst_typednumber.moc"
