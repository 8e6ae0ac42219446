// Video URLs (core/video's VideoSource): what each scheme gives, Sortie's options, an SDP file,
// and a clear error for every bad URL.
#include "VideoSource.h"

#include <QTemporaryDir>
#include <QTest>

using namespace sortie::video;

class TestVideoSource : public QObject
{
    Q_OBJECT

private slots:
    void rtsp()
    {
        const auto parsed = VideoSource::parse(QStringLiteral(" rtsp://10.0.0.5:8554/live?channel=1#latency=40 "));
        QVERIFY2(parsed.source, qPrintable(parsed.error));
        QCOMPARE(parsed.source->transport, VideoTransport::Rtsp);
        QCOMPARE(parsed.source->location, QStringLiteral("rtsp://10.0.0.5:8554/live?channel=1"));  // the server's own query kept
        QCOMPARE(parsed.source->latencyMs, 40);
        QVERIFY(!parsed.source->tcpOnly);
        const auto tcp = VideoSource::parse(QStringLiteral("rtspt://cam/stream"));
        QVERIFY(tcp.source);
        QVERIFY(tcp.source->tcpOnly);
        QCOMPARE(tcp.source->latencyMs, VideoSource::kDefaultLatencyMs);
    }

    void rtpOverUdp()
    {
        const auto plain = VideoSource::parse(QStringLiteral("udp://"));
        QVERIFY2(plain.source, qPrintable(plain.error));
        QCOMPARE(plain.source->transport, VideoTransport::RtpUdp);
        QCOMPARE(plain.source->port, quint16(5600));
        QCOMPARE(plain.source->codec, VideoCodec::H264);
        QVERIFY(plain.source->address.isEmpty());
        const auto h265 = VideoSource::parse(QStringLiteral("udp://239.1.2.3:5004?codec=h265&payload=97&latency=20"));
        QVERIFY2(h265.source, qPrintable(h265.error));
        QCOMPARE(h265.source->address, QStringLiteral("239.1.2.3"));
        QCOMPARE(h265.source->port, quint16(5004));
        QCOMPARE(h265.source->codec, VideoCodec::H265);
        QCOMPARE(h265.source->payloadType, 97);
        QCOMPARE(h265.source->latencyMs, 20);
        QVERIFY(h265.source->rtpCaps().contains(QLatin1String("encoding-name=(string)H265")));
        QVERIFY(h265.source->rtpCaps().contains(QLatin1String("payload=(int)97")));
    }

    void mpegTs()
    {
        const auto ts = VideoSource::parse(QStringLiteral("udp+ts://:5000"));
        QVERIFY2(ts.source, qPrintable(ts.error));
        QCOMPARE(ts.source->transport, VideoTransport::MpegTsUdp);
        QCOMPARE(ts.source->port, quint16(5000));
        // A codec is the stream's own in MPEG-TS: not an option.
        QVERIFY(!VideoSource::parse(QStringLiteral("udp+ts://:5000?codec=h265")).source);
    }

    void sdpFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("camera.sdp"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("v=0\r\no=- 0 0 IN IP4 127.0.0.1\r\ns=camera\r\nc=IN IP4 239.0.0.7/16\r\nt=0 0\r\n"
                   "m=audio 5602 RTP/AVP 0\r\nm=video 5610 RTP/AVP 98\r\na=rtpmap:98 H265/90000\r\n");
        file.close();
        for (const QString &url : {path, QUrl::fromLocalFile(path).toString()}) {
            const auto parsed = VideoSource::parse(url);
            QVERIFY2(parsed.source, qPrintable(parsed.error));
            QCOMPARE(parsed.source->transport, VideoTransport::RtpUdp);
            QCOMPARE(parsed.source->port, quint16(5610));
            QCOMPARE(parsed.source->payloadType, 98);
            QCOMPARE(parsed.source->codec, VideoCodec::H265);
            QCOMPARE(parsed.source->address, QStringLiteral("239.0.0.7"));
        }
        const auto vp8 = VideoSource::fromSdp("v=0\r\no=- 0 0 IN IP4 127.0.0.1\r\ns=x\r\nt=0 0\r\nm=video 5600 RTP/AVP 96\r\na=rtpmap:96 VP8/90000\r\n",
                                              QStringLiteral("x.sdp"));
        QVERIFY(!vp8.source);
        QVERIFY2(vp8.error.contains(QLatin1String("VP8")), qPrintable(vp8.error));
        const auto missing = VideoSource::parse(dir.filePath(QStringLiteral("nowhere.sdp")));
        QVERIFY(!missing.source);
        QVERIFY2(missing.error.contains(QLatin1String("nowhere.sdp")), qPrintable(missing.error));
    }

    void badUrls_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("says");
        QTest::newRow("empty") << QString() << QStringLiteral("no video URL");
        QTest::newRow("not a url") << QStringLiteral("camera one") << QStringLiteral("not a URL");
        QTest::newRow("scheme") << QStringLiteral("http://cam/video") << QStringLiteral("rtsp://, rtspt://, udp://");
        QTest::newRow("port") << QStringLiteral("udp://:0") << QStringLiteral("out of range");
        QTest::newRow("rtsp host") << QStringLiteral("rtsp:///live") << QStringLiteral("needs a host");
        QTest::newRow("codec") << QStringLiteral("udp://:5600?codec=mjpeg") << QStringLiteral("h264 or h265");
        QTest::newRow("latency") << QStringLiteral("rtsp://cam/live#latency=-3") << QStringLiteral("latency");
        QTest::newRow("payload") << QStringLiteral("udp://:5600?payload=33") << QStringLiteral("dynamic RTP payload");
        QTest::newRow("option") << QStringLiteral("udp://:5600?latncy=3") << QStringLiteral("unknown option 'latncy'");
        QTest::newRow("address") << QStringLiteral("udp://camera.local:5600") << QStringLiteral("not an IP address");
    }

    void badUrls()
    {
        QFETCH(QString, url);
        QFETCH(QString, says);
        const auto parsed = VideoSource::parse(url);
        QVERIFY(!parsed.source);
        QVERIFY2(parsed.error.contains(says), qPrintable(parsed.error));
    }
};

QTEST_GUILESS_MAIN(TestVideoSource)
#include "tst_videosource.moc"
