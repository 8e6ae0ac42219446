#pragma once

#include <QImage>
#include <QPalette>
#include <QQmlEngine>
#include <QQuickItem>
#include <QQuickView>

#include <memory>

namespace sortie::test {

// Chooses what every offscreen UI test draws with: the software scene graph and the Fusion
// style. Call before the first window exists (initTestCase).
void useSoftwareRendering();

// The dark palette the UI tests switch to (QGuiApplication::setPalette) to check the dark views.
QPalette darkPalette();

// A real QML scene in an offscreen window: QML text importing Sortie.Ui, loaded, shown and
// exposed. Objects are found by objectName.
class QuickScene
{
public:
    QuickScene(const QByteArray &qml, QSize size = QSize(800, 600),
               const QVariantMap &initialProperties = {});

    bool isReady() const { return m_root != nullptr; }
    QString errors() const { return m_errors; }
    QQuickView &view() { return *m_view; }
    QQmlEngine &engine() { return *m_view->engine(); }
    QQuickItem *root() const { return m_root; }
    template <typename T = QObject>
    T *find(const QString &objectName) const
    {
        return m_root ? m_root->findChild<T *>(objectName) : nullptr;
    }
    QImage grab() { return m_view->grabWindow(); }

private:
    std::unique_ptr<QQuickView> m_view;
    QQuickItem *m_root = nullptr;
    QString m_errors;
};

// The item named `name` at or under `root` in the item tree: a Repeater's delegates are child
// items of the Repeater's parent, not QObject children, so findChild misses them. Null when none.
QQuickItem *findItem(QQuickItem *root, const QString &name);

// Where an item's middle is in its scene: where a test clicks it.
QPointF sceneCentre(QQuickItem *item);

// The fly view (TelemetryPage) alone, as Main.qml makes it: its initial property "graph" is the
// ClientGraph the test made (tst_replayui, tst_photosview).
extern const char *const kTelemetryPageQml;

// How far two colours are apart (largest channel difference).
int colourDistance(QRgb a, QRgb b);
// Number of distinct colours in an image (up to `limit`): a blank image has one.
int distinctColours(const QImage &image, int limit = 64);

} // namespace sortie::test
