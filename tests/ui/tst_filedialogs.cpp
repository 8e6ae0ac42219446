// Every file and folder picker of the whole client opens in the client's window when asked, and
// closes again. Qt 6.4's Qt Quick dialogs find no window when they are made inside a popup before its
// scene is shown (the map source dialog binds parentWindow for that), and they cannot open at all
// without Qt.labs.folderlistmodel: either way an operator's Import or Browse would do nothing.
#include "ClientWindow.h"
#include "QuickScene.h"

#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using sortie::test::ClientWindow;

namespace {

bool isPicker(const QObject *object)
{
    const QByteArray type = object->metaObject()->className();
    return type.startsWith("QQuickFileDialog") || type.startsWith("QQuickFolderDialog");
}

} // namespace

class TestFileDialogs : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { sortie::test::useSoftwareRendering(); }

    void everyPickerOpens()
    {
        ClientWindow::Options options;
        options.vciVehicles = 0;
        options.mannedTraffic = false;
        ClientWindow client(options);
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.logIn());
        client.showPage(1);
        QVERIFY(sortie::test::waitForFrame(client.window()));

        QList<QObject *> pickers;
        for (QObject *object : client.window()->findChildren<QObject *>())
            if (isPicker(object))
                pickers << object;
        // The route's import, export and energy profile, the zones' import, the replay's log and
        // export, and the map source's three rasters.
        QVERIFY2(pickers.size() >= 9, qPrintable(QString::number(pickers.size())));
        for (QObject *picker : pickers) {
            const QString name = QStringLiteral("%1 '%2'").arg(QString::fromLatin1(picker->metaObject()->className()),
                                                               picker->property("title").toString());
            QVERIFY2(picker->property("parentWindow").value<QWindow *>() == client.window(), qPrintable(name));
            QVERIFY(QMetaObject::invokeMethod(picker, "open"));
            QTRY_VERIFY2(picker->property("visible").toBool(), qPrintable(name));
            QVERIFY(QMetaObject::invokeMethod(picker, "reject"));
            QTRY_VERIFY2(!picker->property("visible").toBool(), qPrintable(name));
        }
    }
};

QTEST_MAIN(TestFileDialogs)
#include "tst_filedialogs.moc"
