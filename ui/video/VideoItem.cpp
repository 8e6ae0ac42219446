#include "VideoItem.h"

#include <QFontMetrics>
#include <QPainter>

namespace sortie::ui {

using video::VideoReceiver;

VideoItem::VideoItem(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setOpaquePainting(true);
    setFillColor(Qt::black);
    m_clock.setInterval(1000);
    connect(&m_clock, &QTimer::timeout, this, [this] { update(); });
}

void VideoItem::setReceiver(VideoReceiver *receiver)
{
    if (receiver == m_receiver)
        return;
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_receiver = receiver;
    m_frame = {};
    if (receiver) {
        m_connections << connect(receiver, &VideoReceiver::frameReady, this, &VideoItem::takeFrame)
                      << connect(receiver, &VideoReceiver::stateChanged, this, [this] {
                             m_receiver && m_receiver->state() == VideoReceiver::State::Stalled ? m_clock.start() : m_clock.stop();
                             update();
                         })
                      << connect(receiver, &VideoReceiver::decoderChanged, this, [this] { update(); });
        if (receiver->framesReceived() > 0)
            takeFrame();
    }
    emit receiverChanged();
    update();
}

void VideoItem::setCompact(bool compact)
{
    if (compact == m_compact)
        return;
    m_compact = compact;
    emit compactChanged();
    update();
}

void VideoItem::takeFrame()
{
    if (!m_receiver)
        return;
    m_frame = m_receiver->latestFrame();
    ++m_shown;
    emit frameShown();
    update();
}

void VideoItem::paint(QPainter *painter)
{
    const QRectF area = boundingRect();
    const bool playing = m_receiver && m_receiver->state() == VideoReceiver::State::Playing;
    const bool stalled = m_receiver && m_receiver->state() == VideoReceiver::State::Stalled;
    if (!m_frame.image.isNull() && (playing || stalled)) {
        const QSizeF size = QSizeF(m_frame.image.size()).scaled(area.size(), Qt::KeepAspectRatio);
        const QRectF target(area.center().x() - size.width() / 2, area.center().y() - size.height() / 2, size.width(), size.height());
        painter->setRenderHint(QPainter::SmoothPixmapTransform, !m_compact);
        painter->drawImage(target, m_frame.image);
        if (stalled)
            painter->fillRect(target, QColor(0, 0, 0, 110));  // the last picture, dimmed: it is old
    }
    QString text;
    if (!m_receiver)
        text = tr("No video for this vehicle");
    else if (!playing)
        text = m_receiver->statusText();
    QFont font = painter->font();
    font.setPixelSize(m_compact ? 11 : 14);
    painter->setFont(font);
    const QFontMetrics metrics(font);
    if (!text.isEmpty()) {
        const qreal margin = m_compact ? 6 : 12;
        const QRectF box = area.adjusted(margin, margin, -margin, -margin);
        QRectF bounds = metrics.boundingRect(box.toAlignedRect(), Qt::AlignCenter | Qt::TextWordWrap, text);
        bounds.adjust(-8, -5, 8, 5);
        painter->fillRect(bounds.intersected(area), QColor(0, 0, 0, 170));
        painter->setPen(m_receiver && m_receiver->state() == VideoReceiver::State::Error ? QColor(255, 170, 150) : QColor(235, 235, 235));
        painter->drawText(box, Qt::AlignCenter | Qt::TextWordWrap, text);
    } else if (playing && !m_compact) {
        const QString how = m_receiver->hardwareDecoding() ? tr("hardware decoding (%1)").arg(m_receiver->decoderName())
                                                           : tr("software decoding (%1)").arg(m_receiver->decoderName());
        const QRectF corner(area.right() - metrics.horizontalAdvance(how) - 16, area.bottom() - metrics.height() - 10,
                            metrics.horizontalAdvance(how) + 10, metrics.height() + 4);
        painter->fillRect(corner, QColor(0, 0, 0, 140));
        painter->setPen(QColor(235, 235, 235));
        painter->drawText(corner, Qt::AlignCenter, how);
    }
}

} // namespace sortie::ui
