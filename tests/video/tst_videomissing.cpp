// A system without an H.264 decoder (every one GStreamer has is given rank none, so neither the
// receiver nor decodebin will use it): the receiver says which Debian package to install, instead of
// showing a blank picture.
#include "VideoReceiver.h"
#include "VideoRuntime.h"

#include <QTest>

#include <gst/gst.h>

using namespace sortie::video;

class TestVideoMissing : public QObject
{
    Q_OBJECT

    VideoRuntime m_runtime;

private slots:
    void missingDecoderNamesThePackage()
    {
        QVERIFY2(m_runtime.isAvailable(), qPrintable(m_runtime.errorString()));
        GList *decoders = gst_element_factory_list_get_elements(GST_ELEMENT_FACTORY_TYPE_DECODER, GST_RANK_NONE);
        GstCaps *caps = gst_caps_from_string("video/x-h264");
        GList *h264 = gst_element_factory_list_filter(decoders, caps, GST_PAD_SINK, FALSE);
        QVERIFY2(h264, "this machine has no H.264 decoder to hide");
        for (GList *f = h264; f; f = f->next)
            gst_plugin_feature_set_rank(GST_PLUGIN_FEATURE(f->data), GST_RANK_NONE);
        gst_plugin_feature_list_free(h264);
        gst_plugin_feature_list_free(decoders);
        gst_caps_unref(caps);

        VideoReceiver receiver(m_runtime);
        receiver.setUrl(QStringLiteral("udp://127.0.0.1:5600"));
        QCOMPARE(receiver.state(), VideoReceiver::State::Error);
        QCOMPARE(receiver.missingPackage(), QStringLiteral("gstreamer1.0-libav"));
        QVERIFY2(receiver.statusText().contains(QLatin1String("No H.264 decoder: install gstreamer1.0-libav")), qPrintable(receiver.statusText()));
    }
};

QTEST_GUILESS_MAIN(TestVideoMissing)
#include "tst_videomissing.moc"
