#include "ocr_module.hpp"

#include <utility>

#include "module_options.hpp"
#include "object_list.hpp"
#include "ubii/ocr/error.hpp"
#include "ubii/ocr/tesseract_messages.hpp"

namespace ubii::ocr::modules
{
namespace
{

ModuleDescription describe(std::string name, std::string what, PipelineKind kind)
{
    ModuleDescription description(std::move(name), std::move(what) + " " + arguments_help(kind),
                                  {input<Image2D>("image")},
                                  {output<Object2DList>("objects"), output<std::string>("error")},
                                  TriggerOnInput{}, Executor::worker);
    description.tags = {"ocr", "tesseract", std::string(to_string(kind))};
    description.authors = {"libubii"};
    return description;
}

} // namespace

OcrModule::OcrModule(std::string name, std::string what, PipelineOptions options)
    : ProcessingModule(describe(std::move(name), std::move(what), kind_of(options))),
      options_(std::move(options))
{
}

OcrModule::~OcrModule() = default;

void OcrModule::on_created()
{
    pipeline_ = make_pipeline(options_);
}

void OcrModule::on_processing(Pass &pass)
{
    const Record *frame = pass.record("image");
    if (frame == nullptr)
        return;
    try {
        pass.set_output("objects",
                        to_object2d_list(pipeline_->recognise(image_to_mat(frame->image()))));
    } catch (const ocr::Error &error) {
        // The frame's sender only sees records: an error record says why nothing came back.
        pass.set_output("error",
                        name() + " frame " + std::to_string(pass.number()) + ": " + error.what());
    }
    for (std::string &line : take_tesseract_messages())
        pass.log("tesseract: " + line);
}

void OcrModule::on_destroyed()
{
    pipeline_.reset();
}

TesseractOcrPure::TesseractOcrPure(const ModuleArguments &arguments)
    : OcrModule("TesseractOCR_PURE",
                "Tesseract finds and reads the words of each image (sparse-text segmentation).",
                options_from(PipelineKind::pure, arguments))
{
}

TesseractOcrMser::TesseractOcrMser(const ModuleArguments &arguments)
    : OcrModule("TesseractOCR_MSER",
                "MSER proposes character regions, grouped into lines that Tesseract reads.",
                options_from(PipelineKind::mser, arguments))
{
}

TesseractOcrEast::TesseractOcrEast(const ModuleArguments &arguments)
    : OcrModule("TesseractOCR_EAST",
                "The EAST text detector proposes word boxes that Tesseract reads; needs the "
                "argument model (no EAST model ships with libubii).",
                options_from(PipelineKind::east, arguments))
{
}

TextDetectionDb::TextDetectionDb(const ModuleArguments &arguments)
    : OcrModule("TextDetection_DB",
                "PaddleOCR's PP-OCRv4 DB detector finds text lines at any angle; each is turned "
                "upright and read by Tesseract line by line.",
                options_from(PipelineKind::db, arguments))
{
}

} // namespace ubii::ocr::modules
