// ubii::Protocol: the transitions it allows, the order its hooks run in, holds, nested transitions
// and hooks that throw.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ubii/protocol.hpp"

namespace
{

enum class Light { off, warming, on };

std::string_view light_name(Light light)
{
    switch (light) {
    case Light::off:
        return "off";
    case Light::warming:
        return "warming";
    case Light::on:
        return "on";
    }
    return "?";
}

ubii::Protocol<Light> make_light()
{
    return ubii::Protocol<Light>(
        "light", Light::off,
        {{Light::off, Light::warming}, {Light::warming, Light::on}, {Light::on, Light::off}},
        light_name);
}

TEST(Protocol, RefusesTransitionsItDoesNotList)
{
    auto light = make_light();
    EXPECT_THROW(light.transition(Light::on), ubii::StateError);
    EXPECT_EQ(light.state(), Light::off);
    try {
        light.transition(Light::on);
    } catch (const ubii::StateError &error) {
        EXPECT_STREQ(error.what(), "light: no transition from off to on");
    }
    light.transition(Light::warming);
    light.transition(Light::on);
    EXPECT_EQ(light.state(), Light::on);
    light.force(Light::warming); // a mirrored machine's word is final
    EXPECT_EQ(light.state(), Light::warming);
}

TEST(Protocol, HooksRunTransitionThenEnterThenEveryTransition)
{
    auto light = make_light();
    std::vector<std::string> ran;
    light.on_every_transition([&](ubii::Transition<Light> &) { ran.push_back("every"); });
    light.on_enter(Light::warming, [&](ubii::Transition<Light> &) { ran.push_back("enter"); });
    light.on_transition(Light::off, Light::warming, [&](ubii::Transition<Light> &t) {
        EXPECT_EQ(t.from(), Light::off);
        EXPECT_EQ(t.to(), Light::warming);
        ran.push_back("transition");
    });
    light.on_enter(Light::on, [&](ubii::Transition<Light> &) { ran.push_back("wrong state"); });
    light.transition(Light::warming);
    EXPECT_EQ(ran, (std::vector<std::string>{"transition", "enter", "every"}));
}

TEST(Protocol, AHoldKeepsTheStepUnsettledUntilReleased)
{
    auto light = make_light();
    ubii::Hold hold;
    light.on_enter(Light::warming, [&](ubii::Transition<Light> &t) { hold = t.hold(); });
    EXPECT_TRUE(light.settled());
    light.transition(Light::warming);
    EXPECT_FALSE(light.settled());
    EXPECT_TRUE(hold.active());
    hold.release();
    EXPECT_TRUE(light.settled());
    EXPECT_FALSE(hold.active());
}

TEST(Protocol, HoldsOfAStepLeftAreVoid)
{
    auto light = make_light();
    ubii::Hold hold;
    light.on_enter(Light::warming, [&](ubii::Transition<Light> &t) { hold = t.hold(); });
    light.transition(Light::warming);
    light.transition(Light::on);
    EXPECT_TRUE(light.settled()); // the hold belonged to warming
    EXPECT_FALSE(hold.active());
    hold.release(); // harmless
}

TEST(Protocol, ATransitionAskedForInAHookRunsAfterTheCurrentHooks)
{
    auto light = make_light();
    std::vector<std::string> ran;
    light.on_enter(Light::warming, [&](ubii::Transition<Light> &) {
        light.transition(Light::on);
        ran.push_back("warming first hook");
        EXPECT_EQ(light.state(), Light::warming);
    });
    light.on_enter(Light::warming,
                   [&](ubii::Transition<Light> &) { ran.push_back("warming second hook"); });
    light.on_enter(Light::on, [&](ubii::Transition<Light> &) { ran.push_back("on"); });
    light.transition(Light::warming);
    EXPECT_EQ(ran, (std::vector<std::string>{"warming first hook", "warming second hook", "on"}));
    EXPECT_EQ(light.state(), Light::on);
}

TEST(Protocol, AThrowingHookLetsTheOthersRunAndReachesTheErrorHandler)
{
    auto light = make_light();
    int later_hook_ran = 0;
    light.on_enter(Light::warming,
                   [](ubii::Transition<Light> &) { throw std::runtime_error("bulb broken"); });
    light.on_enter(Light::warming, [&](ubii::Transition<Light> &) { ++later_hook_ran; });
    EXPECT_THROW(light.transition(Light::warming), std::runtime_error); // no handler: rethrown
    EXPECT_EQ(light.state(), Light::warming);
    EXPECT_EQ(later_hook_ran, 1);

    std::vector<std::string> reported;
    light.set_error_handler([&](std::exception_ptr error, const ubii::Transition<Light> &t) {
        try {
            std::rethrow_exception(error);
        } catch (const std::exception &e) {
            reported.push_back(std::string(light_name(t.to())) + ": " + e.what());
        }
    });
    light.on_enter(Light::on,
                   [](ubii::Transition<Light> &) { throw std::runtime_error("too bright"); });
    EXPECT_NO_THROW(light.transition(Light::on));
    EXPECT_EQ(reported, (std::vector<std::string>{"on: too bright"}));
}

TEST(Protocol, RemovedHooksDoNotRun)
{
    auto light = make_light();
    int runs = 0;
    const auto id = light.on_enter(Light::warming, [&](ubii::Transition<Light> &) { ++runs; });
    light.remove_hook(id);
    light.transition(Light::warming);
    EXPECT_EQ(runs, 0);
}

} // namespace
