// The server's no-fly zones: any NoFlightZone payload a server could send is converted or left out
// with a reason; a converted custom zone that can be written back converts again.
#include "Domain.pb.h"
#include "NfzConversion.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    com::ugcs::ucs::proto::NoFlightZone nfz;
    if (!nfz.ParseFromArray(data, int(size)))
        return 0;
    QString why;
    const auto zone = sortie::airspace::NfzConversion::toZone(nfz, &why);
    if (!zone) {
        if (why.isEmpty())
            std::abort();  // a zone left out always says why
        return 0;
    }
    if (const auto back = sortie::airspace::NfzConversion::toNfz(*zone, &nfz, &why))
        (void)sortie::airspace::NfzConversion::toZone(*back, &why);
    return 0;
}
