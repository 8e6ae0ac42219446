#include "RoutePainter.h"

#include <QPaintDevice>
#include <QPainter>

#include <cmath>

namespace sortie::ui {

namespace {
constexpr int kMaxCachedNumbers = 20000;

int digitsOf(int value)
{
    int digits = 1;
    while (value >= 10) {
        value /= 10;
        ++digits;
    }
    return digits;
}
} // namespace

const QStaticText &RoutePainter::number(int value)
{
    auto it = m_numbers.find(value);
    if (it == m_numbers.end()) {
        if (m_numbers.size() > kMaxCachedNumbers)
            m_numbers.clear();
        QStaticText text(QString::number(value));
        text.setTextFormat(Qt::PlainText);
        text.setPerformanceHint(QStaticText::AggressiveCaching);
        text.prepare(QTransform(), m_font);
        it = m_numbers.insert(value, text);
    }
    return it.value();
}

QImage RoutePainter::drawSprite(quint8 flags, int digits) const
{
    const double r = m_style.markerRadius;
    const bool labelled = flags & RouteFrame::Labelled;
    const QColor fill = (flags & RouteFrame::Selected) ? m_style.selected : m_style.marker;
    const double textWidth = QFontMetricsF(m_font).horizontalAdvance(QString(digits, QLatin1Char('8')));
    const double w = labelled ? std::max(2 * r, textWidth + 6) : r * 0.8;
    const double h = labelled ? 2 * r : r * 0.8;
    const double pad = (flags & RouteFrame::Current) && labelled ? 6 : 2;
    const QSizeF size(w + 2 * pad, h + 2 * pad);
    QImage image((size * m_dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(m_dpr);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF body(pad, pad, w, h);
    if (labelled && (flags & RouteFrame::Current)) {
        p.setPen(QPen(m_style.current, 3.0));
        p.setBrush(Qt::NoBrush);
        p.drawRoundedRect(body.adjusted(-4, -4, 4, 4), r + 4, r + 4);
    }
    p.setPen(QPen(m_style.halo, 1.5));
    p.setBrush(fill);
    p.drawRoundedRect(body, h / 2, h / 2);
    return image;
}

const QImage &RoutePainter::sprite(quint8 flags, int digits)
{
    const int key = (flags & RouteFrame::Labelled) ? (int(flags) << 8) | digits : int(flags) << 8;
    auto it = m_sprites.find(key);
    if (it == m_sprites.end())
        it = m_sprites.insert(key, drawSprite(flags, digits));
    return it.value();
}

const QImage &RoutePainter::markSprite(quint8 marks)
{
    auto it = m_markSprites.find(marks);
    if (it != m_markSprites.end())
        return it.value();
    const double d = std::max(8.0, m_style.markerRadius);
    QImage image((QSizeF(d + 2, d + 2) * m_dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(m_dpr);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF body(1, 1, d, d);
    const bool camera = marks & 1, other = marks & 2;
    p.setPen(Qt::NoPen);
    p.setBrush(camera ? m_style.cameraMark : m_style.actionMark);
    p.drawEllipse(body);
    if (camera && other) {  // the right half says "and more"
        p.setBrush(m_style.actionMark);
        p.drawPie(body, -90 * 16, 180 * 16);
    }
    p.setPen(QPen(m_style.halo, 1.2));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(body);
    return m_markSprites.insert(marks, image).value();
}

void RoutePainter::setUp(QPainter &painter, const Style &style)
{
    const qreal dpr = painter.device() ? painter.device()->devicePixelRatioF() : 1.0;
    if (style == m_style && dpr == m_dpr)
        return;
    m_style = style;
    m_dpr = dpr;
    m_font = painter.font();
    m_font.setPixelSize(int(style.markerRadius * 1.1));
    m_font.setBold(true);
    m_numbers.clear();
    m_sprites.clear();
    m_markSprites.clear();
}

void RoutePainter::paintLegs(QPainter &painter, const std::vector<QPolygonF> &legs)
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(m_style.halo, m_style.legWidth + 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const QPolygonF &leg : legs)
        painter.drawPolyline(leg);
    painter.setPen(QPen(m_style.leg, m_style.legWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const QPolygonF &leg : legs)
        painter.drawPolyline(leg);
}

void RoutePainter::paintMarkers(QPainter &painter, const std::vector<RouteFrame::Marker> &markers)
{
    painter.setFont(m_font);
    painter.setPen(m_style.text);
    for (const RouteFrame::Marker &marker : markers) {
        const int value = marker.row + 1;
        const QImage &image = sprite(marker.flags, digitsOf(value));
        const QSizeF size = image.deviceIndependentSize();
        // Whole pixels: a blit, not a resampling.
        const QPointF topLeft(std::round(marker.position.x() - size.width() / 2),
                              std::round(marker.position.y() - size.height() / 2));
        painter.drawImage(topLeft, image);
        if (marker.flags & RouteFrame::Labelled) {
            const QStaticText &text = number(value);
            painter.drawStaticText(marker.position - QPointF(text.size().width() / 2, text.size().height() / 2), text);
            if (marker.marks) {
                const QImage &mark = markSprite(marker.marks);
                const double r = m_style.markerRadius;
                painter.drawImage(QPointF(std::round(topLeft.x() + size.width() - r * 0.6), std::round(marker.position.y() - r * 1.5)), mark);
            }
        }
    }
}

void RoutePainter::paintStill(QPainter &painter, const RouteFrame &frame, const Style &style)
{
    setUp(painter, style);
    paintLegs(painter, frame.legs);
    paintMarkers(painter, frame.markers);
}

void RoutePainter::paintMoving(QPainter &painter, const RouteFrame &frame, const Style &style, QPointF origin)
{
    setUp(painter, style);
    painter.translate(-origin);
    paintLegs(painter, frame.movingLegs);
    paintMarkers(painter, frame.movingMarkers);
}

QRectF RoutePainter::movingBounds(const RouteFrame &frame, const Style &style)
{
    QRectF bounds;
    const double legPad = style.legWidth + 4.0;
    for (const QPolygonF &leg : frame.movingLegs)
        bounds |= leg.boundingRect().adjusted(-legPad, -legPad, legPad, legPad);
    // A marker sprite: the number's width (five digits at most fit), the current ring, the halo.
    const QPointF half(style.markerRadius * 3 + 10, style.markerRadius + 10);
    for (const RouteFrame::Marker &marker : frame.movingMarkers)
        bounds |= QRectF(marker.position - half, marker.position + half);
    return bounds;
}

} // namespace sortie::ui
