#include "AtomicFile.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>

#include <fcntl.h>
#include <unistd.h>

namespace sortie::client {

QString writeFileAtomically(const QString &path, const QByteArray &data)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QCoreApplication::translate("AtomicFile", "Cannot write %1: %2").arg(path, file.errorString());
    // 0600 whatever the umask: what is written this way (autosaves) is the operator's alone.
    file.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    if (file.write(data) != data.size()) {
        const QString error = file.errorString();
        file.cancelWriting();
        return QCoreApplication::translate("AtomicFile", "Cannot write %1: %2").arg(path, error);
    }
    if (!file.commit()) // flush, fsync, rename
        return QCoreApplication::translate("AtomicFile", "Cannot write %1: %2").arg(path, file.errorString());
    // The rename is durable only once the directory entry is: fsync the directory too.
    const QByteArray directory = QFile::encodeName(QFileInfo(path).absolutePath());
    const int fd = ::open(directory.constData(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    return {};
}

} // namespace sortie::client
