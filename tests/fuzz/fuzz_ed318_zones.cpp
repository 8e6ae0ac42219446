// EUROCAE ED-318 zone reader: any bytes are read or refused, a bad feature is a problem, never a
// crash; what an accepted file must hold is GeoZoneFuzzCheck.h's, shared with the other reader.
#include "GeoZoneFuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    sortie_fuzz::checkGeoZoneRead(sortie::airspace::ed::readEd318(bytes));
    return 0;
}
