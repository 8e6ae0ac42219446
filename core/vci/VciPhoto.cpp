#include "VciPhoto.h"

#include <cmath>
#include <numbers>

namespace sortie::vci::profile {

namespace {

using json = nlohmann::json;

// Whole numbers of milliseconds or photos fit a double exactly up to 2^53.
constexpr double kLargestWhole = 9007199254740992.0;

bool fail(std::string *error, std::string why)
{
    if (error)
        *error = std::move(why);
    return false;
}

// A key that is absent is fine (nullopt); one that is there must be a finite number.
bool optionalNumber(const json &body, const char *key, std::optional<double> *out, std::string *error)
{
    const auto it = body.find(key);
    if (it == body.end() || it->is_null())
        return true;
    if (!it->is_number() || !std::isfinite(it->get<double>()))
        return fail(error, std::string(key) + ": not a finite number");
    *out = it->get<double>();
    return true;
}

bool wholeNumber(const json &body, const char *key, double least, int64_t *out, std::string *error)
{
    const auto it = body.find(key);
    if (it == body.end())
        return fail(error, std::string(key) + ": missing");
    const double v = it->is_number() ? it->get<double>() : std::nan("");
    if (!(v >= least && v <= kLargestWhole && std::floor(v) == v))
        return fail(error, std::string(key) + ": not a whole number from " + std::to_string(int64_t(least)));
    *out = int64_t(v);
    return true;
}

bool angle(const json &body, const char *key, double limit, double *out, std::string *error)
{
    std::optional<double> v;
    if (!optionalNumber(body, key, &v, error))
        return false;
    if (!v)
        return fail(error, std::string(key) + ": missing");
    if (std::abs(*v) > limit)
        return fail(error, std::string(key) + ": off the globe (radians expected)");
    *out = *v;
    return true;
}

void put(json &body, const char *key, const std::optional<double> &value)
{
    if (value)
        body[key] = *value;
}

} // namespace

json encodePhoto(const Photo &photo)
{
    json body = {{"sequence", photo.sequence}, {"time", photo.time}, {"latitude", photo.latitude}, {"longitude", photo.longitude}};
    put(body, "altitudeAmsl", photo.altitudeAmsl);
    put(body, "altitudeAgl", photo.altitudeAgl);
    put(body, "roll", photo.roll);
    put(body, "pitch", photo.pitch);
    put(body, "yaw", photo.yaw);
    put(body, "gimbalTilt", photo.gimbalTilt);
    return body;
}

std::optional<Photo> decodePhoto(const json &body, std::string *error)
{
    if (error)
        error->clear();
    if (body.is_null())
        return std::nullopt;
    if (!body.is_object()) {
        fail(error, "a photo is a JSON object");
        return std::nullopt;
    }
    Photo p;
    if (!wholeNumber(body, "sequence", 1, &p.sequence, error) || !wholeNumber(body, "time", 0, &p.time, error)
        || !angle(body, "latitude", std::numbers::pi / 2, &p.latitude, error) || !angle(body, "longitude", std::numbers::pi, &p.longitude, error)
        || !optionalNumber(body, "altitudeAmsl", &p.altitudeAmsl, error) || !optionalNumber(body, "altitudeAgl", &p.altitudeAgl, error)
        || !optionalNumber(body, "roll", &p.roll, error) || !optionalNumber(body, "pitch", &p.pitch, error)
        || !optionalNumber(body, "yaw", &p.yaw, error) || !optionalNumber(body, "gimbalTilt", &p.gimbalTilt, error))
        return std::nullopt;
    return p;
}

} // namespace sortie::vci::profile
