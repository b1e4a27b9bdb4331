#include "ocr_test_support.hpp"

#include <map>

namespace ubii::ocr::test
{

const testdata::Scene &scene(const std::string &name)
{
    static const std::map<std::string, testdata::Scene> scenes = [] {
        std::map<std::string, testdata::Scene> made;
        for (auto &generated : testdata::all_scenes())
            made.emplace(generated.name, std::move(generated));
        return made;
    }();
    return scenes.at(name);
}

PipelineOptions options_for(PipelineKind kind, const testdata::Scene &scene)
{
    auto options = default_options(kind);
    if (kind == PipelineKind::pure && scene.name != "baseline")
        tesseract_options(options).segmentation = Segmentation::sparse_text;
    if (auto *east = std::get_if<EastOptions>(&options)) {
        east->model_path = UBII_OCR_EAST_TEST_MODEL;
        east->input_size = testdata::east_test_input_size(scene);
    }
    if (auto *db = std::get_if<DbOptions>(&options))
        db->model_path = UBII_OCR_DB_MODEL;
    return options;
}

} // namespace ubii::ocr::test
