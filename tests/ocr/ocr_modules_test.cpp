// The OCR plugin as ubii-node loads it: its four modules, their arguments, and passes through a
// scheduler as a node runs them (worker executor, latest frame wins, errors as records).
#include <chrono>
#include <memory>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ocr_test_support.hpp"
#include "ubii/module_discovery.hpp"
#include "ubii/ocr/image_records.hpp"
#include "ubii/scheduler.hpp"
#include "ubii/standalone_module.hpp"

namespace
{

using namespace std::chrono_literals;
using ::testing::HasSubstr;
namespace ocr = ubii::ocr;

ubii::ModuleRegistry plugin_modules()
{
    ubii::ModuleRegistry registry;
    for (const auto &report : ubii::load_plugins(registry, UBII_OCR_PLUGIN))
        EXPECT_TRUE(report.errors.empty()) << report.errors.front();
    return registry;
}

ubii::Image2D image_record(const cv::Mat &bgr)
{
    const ocr::Image2DData data = ocr::mat_to_image(bgr);
    ubii::Image2D image;
    image.set_width(data.width);
    image.set_height(data.height);
    image.set_data_format(static_cast<ubii::Image2D::DataFormat>(data.format));
    image.set_data(data.data.data(), data.data.size());
    return image;
}

// One module as a node runs it (worker passes, outputs handed on in this thread), outputs
// collected.
class ModuleInScheduler
{
  public:
    explicit ModuleInScheduler(std::unique_ptr<ubii::ProcessingModule> module)
        : module_(std::move(module))
    {
        module_.scheduler().on_output(
            [this](const ubii::ProcessingModule &, const ubii::PassOutput &out) {
                outputs_.push_back(out);
                return ubii::Status::ok;
            });
    }
    void feed(const ubii::Image2D &image)
    {
        module_.feed("image", std::make_shared<const ubii::Record>("/in", image));
    }
    // Runs until `count` outputs arrived or `timeout` passed.
    bool wait_for_outputs(std::size_t count, std::chrono::milliseconds timeout)
    {
        return module_.run_until([&] { return outputs_.size() >= count; }, timeout);
    }
    const std::vector<ubii::PassOutput> &outputs() const
    {
        return outputs_;
    }
    ubii::Timing timing() const
    {
        return module_.timing();
    }

  private:
    std::vector<ubii::PassOutput> outputs_;
    ubii::StandaloneModule module_;
};

std::vector<ocr::TextBox> words_of(const ubii::Object2DList &list)
{
    std::vector<ocr::TextBox> words;
    for (const auto &object : list.elements())
        words.push_back(
            {object.id(), 100.0f,
             cv::Rect(static_cast<int>(object.pose().position().x()),
                      static_cast<int>(object.pose().position().y()),
                      static_cast<int>(object.size().x()), static_cast<int>(object.size().y())),
             std::nullopt});
    return words;
}

TEST(OcrPlugin, OffersTheFourModulesWithImageInAndObjectsAndErrorOut)
{
    const ubii::ModuleRegistry registry = plugin_modules();
    EXPECT_EQ(registry.names(),
              (std::vector<std::string>{"TesseractOCR_EAST", "TesseractOCR_MSER",
                                        "TesseractOCR_PURE", "TextDetection_DB"}));
    for (const std::string &name : registry.names()) {
        const auto &spec = registry.spec(name);
        ASSERT_EQ(spec.inputs_size(), 1) << name;
        EXPECT_EQ(spec.inputs(0).internal_name(), "image");
        EXPECT_EQ(spec.inputs(0).message_format(), "ubii.dataStructure.Image2D");
        ASSERT_EQ(spec.outputs_size(), 2) << name;
        EXPECT_EQ(spec.outputs(0).internal_name(), "objects");
        EXPECT_EQ(spec.outputs(0).message_format(), "ubii.dataStructure.Object2DList");
        EXPECT_EQ(spec.outputs(1).internal_name(), "error");
        EXPECT_THAT(spec.description(), HasSubstr("min_confidence"));
    }
}

TEST(OcrPlugin, ArgumentsOutOfRangeOrMisspeltAreRefusedWhenConfigured)
{
    ubii::ModuleRegistry registry = plugin_modules();
    EXPECT_THAT(
        [&] {
            registry.configure("TesseractOCR_PURE", {{"min_confidence", "200"}});
        },
        ::testing::Throws<ocr::InvalidArgument>());
    EXPECT_THROW(registry.configure("TesseractOCR_PURE", {{"min_confidence", "high"}}),
                 ubii::InvalidArgument);
    EXPECT_THROW(registry.configure("TesseractOCR_PURE", {{"psm", "diagonal"}}),
                 ocr::InvalidArgument);
    EXPECT_THROW(registry.configure("TesseractOCR_EAST", {{"input_size", "300x320"}}),
                 ocr::InvalidArgument);
    EXPECT_THROW(registry.configure("TextDetection_DB", {{"input_size", "8"}}),
                 ocr::InvalidArgument);
    EXPECT_THROW(registry.configure("TesseractOCR_PURE", {{"langauge", "deu"}}),
                 ubii::InvalidArgument);
    EXPECT_NO_THROW(registry.configure("TesseractOCR_PURE", {{"psm", "auto"}, {"lang", "eng"}}));
}

TEST(OcrPlugin, TheEastModuleWithoutAModelFailsToStartSayingWhy)
{
    const ubii::ModuleRegistry registry = plugin_modules();
    ubii::Scheduler scheduler;
    try {
        scheduler.add(registry.create("TesseractOCR_EAST"));
        ADD_FAILURE() << "started without a model";
    } catch (const ocr::ModelError &error) {
        EXPECT_THAT(error.what(), HasSubstr("the module argument model"));
    }
}

TEST(OcrPlugin, PureReadsTheSceneAndAMalformedFrameGivesAnErrorRecord)
{
    const auto &scene = ocr::test::scene("sign");
    ModuleInScheduler module(plugin_modules().create("TesseractOCR_PURE"));
    module.feed(image_record(scene.image));
    ASSERT_TRUE(module.wait_for_outputs(1, 30s));
    ASSERT_EQ(module.outputs()[0].name, "objects");
    const auto score = ocr::testdata::score_words(
        words_of(module.outputs()[0].value.as<ubii::Object2DList>()), scene.words);
    EXPECT_GE(score.recall(), 0.65) << ocr::testdata::describe(score);

    ubii::Image2D malformed = image_record(scene.image);
    malformed.mutable_data()->resize(malformed.data().size() - 3);
    module.feed(malformed);
    ASSERT_TRUE(module.wait_for_outputs(2, 30s));
    ASSERT_EQ(module.outputs()[1].name, "error");
    EXPECT_THAT(module.outputs()[1].value.as<std::string>(),
                ::testing::MatchesRegex("TesseractOCR_PURE frame 2: Image2D of 1200x900x3 needs "
                                        "3240000 bytes, it has 3239997"));
    EXPECT_EQ(module.timing().errors, 0u); // answered, not thrown
}

TEST(OcrPlugin, FramesArrivingDuringAPassReplaceEachOtherAndAreCounted)
{
    const auto &scene = ocr::test::scene("webcam");
    const ubii::Image2D frame = image_record(scene.image);
    ModuleInScheduler module(plugin_modules().create("TesseractOCR_PURE"));
    module.feed(frame); // starts a pass on the worker
    module.feed(frame); // waits
    module.feed(frame); // replaces the waiting one
    ASSERT_TRUE(module.wait_for_outputs(2, 30s));
    EXPECT_FALSE(module.wait_for_outputs(3, 500ms)) << "a replaced frame was read";
    EXPECT_EQ(module.timing().inputs_dropped, 1u);
    EXPECT_EQ(module.timing().passes, 2u);
}

TEST(OcrPlugin, DbReadsTheTiltedSignFromItsModel)
{
    const auto &scene = ocr::test::scene("sign");
    ubii::ModuleRegistry registry = plugin_modules();
    registry.configure("TextDetection_DB", {{"model", UBII_OCR_DB_MODEL}});
    ModuleInScheduler module(registry.create("TextDetection_DB"));
    module.feed(image_record(scene.image));
    ASSERT_TRUE(module.wait_for_outputs(1, 30s));
    ASSERT_EQ(module.outputs()[0].name, "objects");
    const auto score = ocr::testdata::score_words(
        words_of(module.outputs()[0].value.as<ubii::Object2DList>()), scene.words);
    EXPECT_GE(score.recall(), 0.95) << ocr::testdata::describe(score);
    EXPECT_GE(score.precision(), 0.80) << ocr::testdata::describe(score);
}

} // namespace
