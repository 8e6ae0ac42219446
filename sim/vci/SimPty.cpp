#include "SimPty.h"

#include <QSocketNotifier>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace sortie::sim {

SimPty::SimPty(QObject *parent)
    : QIODevice(parent)
{
    m_peerPoll.setInterval(50);
    connect(&m_peerPoll, &QTimer::timeout, this, &SimPty::pollPeer);
}

SimPty::~SimPty()
{
    close();
}

bool SimPty::create(QString *error)
{
    auto fail = [&](const char *what) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(QLatin1String(what), QString::fromLocal8Bit(std::strerror(errno)));
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = -1;
        return false;
    };
    m_fd = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (m_fd < 0)
        return fail("posix_openpt");
    if (::grantpt(m_fd) != 0)
        return fail("grantpt");
    if (::unlockpt(m_fd) != 0)
        return fail("unlockpt");
    const char *name = ::ptsname(m_fd);
    if (!name)
        return fail("ptsname");
    m_slaveName = QString::fromLocal8Bit(name);
    // Raw, or the line discipline would echo our own output back to us and edit lines.
    termios t {};
    if (::tcgetattr(m_fd, &t) == 0) {
        ::cfmakeraw(&t);
        ::tcsetattr(m_fd, TCSANOW, &t);
    }
    m_readNotifier = new QSocketNotifier(qintptr(m_fd), QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &SimPty::onReadable);
    m_writeNotifier = new QSocketNotifier(qintptr(m_fd), QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &SimPty::flush);
    return QIODevice::open(QIODevice::ReadWrite | QIODevice::Unbuffered);
}

void SimPty::close()
{
    if (m_fd < 0)
        return;
    QIODevice::close();
    m_peerPoll.stop();
    delete m_readNotifier;
    delete m_writeNotifier;
    m_readNotifier = m_writeNotifier = nullptr;
    ::close(m_fd);
    m_fd = -1;
    m_in.clear();
    m_out.clear();
}

void SimPty::onReadable()
{
    char buf[16384];
    bool got = false;
    for (;;) {
        const ssize_t n = ::read(m_fd, buf, sizeof buf);
        if (n > 0) {
            m_in.append(buf, qsizetype(n));
            got = true;
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno == EIO)
            markPeerClosed(); // no client has the slave open
        break;
    }
    if (got)
        emit readyRead();
}

void SimPty::markPeerClosed()
{
    if (m_peerClosed)
        return;
    m_peerClosed = true;
    m_out.clear();
    m_readNotifier->setEnabled(false); // it would fire without end while nobody holds the slave
    m_writeNotifier->setEnabled(false);
    m_peerPoll.start();
    emit peerGone();
}

void SimPty::pollPeer()
{
    char c;
    const ssize_t n = ::read(m_fd, &c, 1);
    if (n < 0 && errno == EIO)
        return; // still nobody
    m_peerClosed = false;
    m_peerPoll.stop();
    m_readNotifier->setEnabled(true);
    emit peerReturned();
    if (n == 1) {
        m_in.append(c);
        emit readyRead();
    }
}

qint64 SimPty::readData(char *data, qint64 maxSize)
{
    const qint64 n = std::min<qint64>(maxSize, m_in.size());
    std::memcpy(data, m_in.constData(), size_t(n));
    m_in.remove(0, n);
    return n;
}

qint64 SimPty::writeData(const char *data, qint64 size)
{
    if (m_fd < 0)
        return -1;
    if (m_peerClosed)
        return size; // nobody listens: drop it rather than hand stale bytes to the next client
    m_out.append(data, qsizetype(size));
    flush();
    return size;
}

void SimPty::flush()
{
    while (!m_out.isEmpty()) {
        const ssize_t n = ::write(m_fd, m_out.constData(), size_t(m_out.size()));
        if (n > 0) {
            m_out.remove(0, qsizetype(n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break; // EAGAIN: the line is full, wait until it drains
    }
    m_writeNotifier->setEnabled(!m_out.isEmpty());
}

} // namespace sortie::sim
