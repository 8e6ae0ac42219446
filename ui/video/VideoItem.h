#pragma once

#include "VideoReceiver.h"

#include <QImage>
#include <QPointer>
#include <QQuickPaintedItem>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// A vehicle's live video (docs/video.md): the receiver's latest frame, scaled to fit (its aspect
// kept, black bars), drawn with QPainter so it shows under the software scene graph and offscreen
// as under OpenGL; and over it what the operator must know: "Connecting…", "No video since
// 14:02:07 (00:07)", the package a missing decoder is in, and in a corner how it is decoded
// (hardware or software). Takes a frame each time the receiver says one is ready; a frame the item
// had no time to draw is replaced by the next (the receiver counts it as dropped).
class VideoItem : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(sortie::video::VideoReceiver *receiver READ receiver WRITE setReceiver NOTIFY receiverChanged FINAL)
    Q_PROPERTY(bool compact READ isCompact WRITE setCompact NOTIFY compactChanged FINAL)
    Q_PROPERTY(quint64 framesShown READ framesShown NOTIFY frameShown FINAL)

public:
    explicit VideoItem(QQuickItem *parent = nullptr);

    video::VideoReceiver *receiver() const { return m_receiver; }
    void setReceiver(video::VideoReceiver *receiver);
    // Picture in picture: smaller words, no decoder line.
    bool isCompact() const { return m_compact; }
    void setCompact(bool compact);
    quint64 framesShown() const { return m_shown; }
    // The frame drawn last (tests read its stamp).
    video::VideoFrame currentFrame() const { return m_frame; }

    void paint(QPainter *painter) override;

signals:
    void receiverChanged();
    void compactChanged();
    void frameShown();

private:
    void takeFrame();

    QPointer<video::VideoReceiver> m_receiver;
    QList<QMetaObject::Connection> m_connections;
    video::VideoFrame m_frame;
    quint64 m_shown = 0;
    bool m_compact = false;
    QTimer m_clock;  // the stalled text counts the seconds
};

} // namespace sortie::ui
