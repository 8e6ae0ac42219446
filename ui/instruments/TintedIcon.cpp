#include "TintedIcon.h"

#include <QLoggingCategory>
#include <QPainter>
#include <QQuickWindow>

#include <algorithm>

Q_LOGGING_CATEGORY(lcIcons, "sortie.ui.icons")

namespace sortie::ui {

namespace {
QImage load(const QString &name)
{
    if (name.isEmpty())
        return {};
    QImage image(QStringLiteral(":/sortie/icons/%1.png").arg(name));
    if (image.isNull())
        qCWarning(lcIcons) << "no built-in icon" << name;
    return image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
}

// `source` scaled to `side` pixels, in `colour` where it is drawn (its alpha kept).
QImage tint(const QImage &source, const QColor &colour, int side)
{
    QImage image = source.scaled(side, side, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QPainter painter(&image);
    painter.setCompositionMode(QPainter::CompositionMode_SourceIn);
    painter.fillRect(image.rect(), colour);
    return image;
}
} // namespace

TintedIcon::TintedIcon(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setImplicitSize(24, 24);
    setAntialiasing(true);
}

void TintedIcon::setName(const QString &name)
{
    if (name == m_name)
        return;
    m_name = name;
    m_source = load(name);
    update();
    emit nameChanged();
}

void TintedIcon::setColor(const QColor &color)
{
    if (color == m_color)
        return;
    m_color = color;
    update();
    emit colorChanged();
}

QImage TintedIcon::tinted(const QString &name, const QColor &colour, int size)
{
    const QImage source = load(name);
    if (source.isNull() || size <= 0)
        return {};
    return tint(source, colour, size);
}

void TintedIcon::paint(QPainter *painter)
{
    if (m_source.isNull())
        return;
    const qreal ratio = window() ? window()->effectiveDevicePixelRatio() : 1.0;
    const int side = int(std::min(width(), height()) * ratio);
    if (side <= 0)
        return;
    QImage image = tint(m_source, m_color, side);
    image.setDevicePixelRatio(ratio);
    const QSizeF shown = QSizeF(image.size()) / ratio;
    painter->drawImage(QPointF((width() - shown.width()) / 2, (height() - shown.height()) / 2), image);
}

} // namespace sortie::ui
