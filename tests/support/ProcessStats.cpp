#include "ProcessStats.h"

#include <QDir>
#include <QFile>
#include <QString>

#include <unistd.h>

#ifdef SORTIE_TEST_ASAN
#include <sanitizer/allocator_interface.h>
#else
#include <malloc.h>
#endif

namespace sortie::test {

namespace {

qint64 statusKiB(const QByteArray &status, const QByteArray &key)
{
    const int at = status.indexOf(key + ':');
    if (at < 0)
        return 0;
    const int end = status.indexOf('\n', at);
    return status.mid(at + key.size() + 1, end - at - key.size() - 1).trimmed().split(' ').value(0).toLongLong();
}

// utime + stime from /proc/<pid>/stat: fields 14 and 15, counted after the ")" that ends the name.
double statCpuSeconds(const QByteArray &stat)
{
    const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return 0;
    return double(fields[11].toLongLong() + fields[12].toLongLong()) / double(::sysconf(_SC_CLK_TCK));
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

qint64 heapBytesInUse()
{
#ifdef SORTIE_TEST_ASAN
    return qint64(__sanitizer_get_current_allocated_bytes());
#else
    const struct mallinfo2 info = ::mallinfo2();
    return qint64(info.uordblks + info.hblkhd);
#endif
}

ProcessStats ProcessStats::of(qint64 pid)
{
    const QString dir = pid > 0 ? QStringLiteral("/proc/%1").arg(pid) : QStringLiteral("/proc/self");
    const QByteArray status = readAll(dir + QStringLiteral("/status"));
    ProcessStats stats;
    stats.residentKiB = statusKiB(status, "VmRSS");
    stats.peakResidentKiB = statusKiB(status, "VmHWM");
    stats.openFiles = int(QDir(dir + QStringLiteral("/fd")).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::System).size());
    stats.cpuSeconds = statCpuSeconds(readAll(dir + QStringLiteral("/stat")));
    return stats;
}

} // namespace sortie::test
