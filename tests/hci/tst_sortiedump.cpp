// The sortie-dump program: a capture from a file or from stdin becomes JSON lines on stdout.
#include <QJsonDocument>
#include "TestData.h"
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

namespace {

QByteArray vector(const char *name)
{
    QFile f((QString::fromUtf8(sortieTestData()) + QStringLiteral("/hci-vectors/")) + QLatin1String(name));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QList<QJsonObject> lines(const QByteArray &out)
{
    QList<QJsonObject> objects;
    for (const QByteArray &line : out.split('\n'))
        if (!line.isEmpty())
            objects.append(QJsonDocument::fromJson(line).object());
    return objects;
}

} // namespace

class TestSortieDump : public QObject
{
    Q_OBJECT

private slots:
    void dumpsAFile()
    {
        QProcess dump;
        dump.start(QStringLiteral(SORTIE_DUMP_PROGRAM), {(QString::fromUtf8(sortieTestData()) + QStringLiteral("/hci-vectors/stream-bad-frames.bin"))});
        QVERIFY(dump.waitForFinished(10000));
        QCOMPARE(dump.exitCode(), 0);
        const auto objects = lines(dump.readAllStandardOutput());
        QCOMPARE(objects.size(), 9);
        QCOMPARE(objects[0][QStringLiteral("message")].toString(), QStringLiteral("AuthorizeHciResponse"));
        QCOMPARE(objects[1][QStringLiteral("dropped")].toString(), QStringLiteral("bad signature"));
    }

    void dumpsStdin()
    {
        QProcess dump;
        dump.start(QStringLiteral(SORTIE_DUMP_PROGRAM), {QStringLiteral("-")});
        QVERIFY(dump.waitForStarted(10000));
        dump.write(vector("001-AuthorizeHciRequest.bin") + vector("007-LoginRequest.bin"));
        dump.closeWriteChannel();
        QVERIFY(dump.waitForFinished(10000));
        const auto objects = lines(dump.readAllStandardOutput());
        QCOMPARE(objects.size(), 2);
        QCOMPARE(objects[1][QStringLiteral("offset")].toInt(), 40);
        QCOMPARE(objects[1][QStringLiteral("json")].toObject()[QStringLiteral("userPassword")].toString(), QStringLiteral("***"));
    }

    void namesAMissingFile()
    {
        QProcess dump;
        dump.start(QStringLiteral(SORTIE_DUMP_PROGRAM), {QStringLiteral("/no/such/capture.bin")});
        QVERIFY(dump.waitForFinished(10000));
        QCOMPARE(dump.exitCode(), 1);
        QVERIFY(dump.readAllStandardError().contains("/no/such/capture.bin"));
    }
};

QTEST_MAIN(TestSortieDump)
#include "tst_sortiedump.moc"
