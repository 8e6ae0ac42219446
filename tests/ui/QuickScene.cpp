#include "QuickScene.h"

#include "SortieUi.h"

#include <QQmlComponent>
#include <QQuickStyle>
#include <QQuickWindow>
#include <QSGRendererInterface>
#include <QSet>
#include <QTest>

#include <cstdlib>

namespace sortie::test {

void useSoftwareRendering()
{
    QQuickWindow::setGraphicsApi(QSGRendererInterface::Software);
    QQuickStyle::setStyle(QStringLiteral("Fusion"));
}

QuickScene::QuickScene(const QByteArray &qml, QSize size, const QVariantMap &initialProperties)
    : m_view(std::make_unique<QQuickView>())
{
    sortie::ui::addImportPaths(*m_view->engine());
    QQmlComponent component(m_view->engine());
    component.setData(qml, QUrl(QStringLiteral("qrc:/test/Scene.qml")));
    if (component.isError()) {
        m_errors = component.errorString();
        return;
    }
    QObject *object = component.createWithInitialProperties(initialProperties);
    m_root = qobject_cast<QQuickItem *>(object);
    if (!m_root) {
        m_errors = component.errorString().isEmpty() ? QStringLiteral("the scene's root is not an Item") : component.errorString();
        delete object;
        return;
    }
    m_view->setResizeMode(QQuickView::SizeRootObjectToView);
    m_view->setContent(QUrl(), nullptr, m_root);
    m_view->resize(size);
    m_view->show();
    if (!QTest::qWaitForWindowExposed(m_view.get()))
        m_errors = QStringLiteral("the window was never exposed");
}

int colourDistance(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

QPalette darkPalette()
{
    QPalette dark;
    dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    dark.setColor(QPalette::WindowText, QColor(0xe0, 0xe0, 0xe0));
    dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    dark.setColor(QPalette::AlternateBase, QColor(0x33, 0x33, 0x33));
    dark.setColor(QPalette::Text, QColor(0xe0, 0xe0, 0xe0));
    dark.setColor(QPalette::Button, QColor(0x35, 0x35, 0x35));
    dark.setColor(QPalette::ButtonText, QColor(0xe0, 0xe0, 0xe0));
    dark.setColor(QPalette::ToolTipBase, QColor(0x35, 0x35, 0x35));
    dark.setColor(QPalette::ToolTipText, QColor(0xe0, 0xe0, 0xe0));
    return dark;
}

QPointF sceneCentre(QQuickItem *item)
{
    return item->mapToScene(QPointF(item->width() / 2, item->height() / 2));
}

const char *const kTelemetryPageQml = R"(
    import QtQuick
    import Sortie.Ui
    TelemetryPage {
        units: DisplayUnits {}
        theme: Theme {}
    }
)";

QQuickItem *findItem(QQuickItem *root, const QString &name)
{
    if (!root || root->objectName() == name)
        return root;
    for (QQuickItem *child : root->childItems())
        if (QQuickItem *found = findItem(child, name))
            return found;
    return nullptr;
}

int distinctColours(const QImage &image, int limit)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 3) {
        for (int x = 0; x < image.width(); x += 3) {
            colours.insert(image.pixel(x, y));
            if (colours.size() >= limit)
                return limit;
        }
    }
    return int(colours.size());
}

} // namespace sortie::test
