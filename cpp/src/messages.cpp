#include "ubii/messages.hpp"

#include "ubii/behaviour.hpp"

namespace ubii
{

Vector2 vector2(double x, double y)
{
    Vector2 v;
    v.set_x(x);
    v.set_y(y);
    return v;
}

Vector3 vector3(double x, double y, double z)
{
    Vector3 v;
    v.set_x(x);
    v.set_y(y);
    v.set_z(z);
    return v;
}

Vector4 vector4(double x, double y, double z, double w)
{
    Vector4 v;
    v.set_x(x);
    v.set_y(y);
    v.set_z(z);
    v.set_w(w);
    return v;
}

Quaternion quaternion(double x, double y, double z, double w)
{
    Quaternion q;
    q.set_x(x);
    q.set_y(y);
    q.set_z(z);
    q.set_w(w);
    return q;
}

Color color(double r, double g, double b, double a)
{
    Color c;
    c.set_r(r);
    c.set_g(g);
    c.set_b(b);
    c.set_a(a);
    return c;
}

std::string_view to_string(Behaviour behaviour) noexcept
{
    switch (behaviour) {
    case Behaviour::subscriptions:
        return "subscriptions";
    case Behaviour::publishing:
        return "publishing";
    case Behaviour::services:
        return "services";
    case Behaviour::devices:
        return "devices";
    case Behaviour::processing_modules:
        return "processing_modules";
    }
    return "unknown behaviour";
}

} // namespace ubii
