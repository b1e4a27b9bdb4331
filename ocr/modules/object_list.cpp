#include "object_list.hpp"

#include "ubii/ocr/image_records.hpp"
#include "user_data_json.hpp"

namespace ubii::ocr::modules
{

cv::Mat image_to_mat(const ImageView &image)
{
    const ubii_image_view view{image.width, image.height,
                               static_cast<ubii_dataStructure_Image2D_DataFormat>(image.format),
                               image.data, image.size};
    return ocr::image_to_mat(view);
}

Object2DList to_object2d_list(const std::vector<TextBox> &words)
{
    Object2DList list;
    for (const auto &word : words) {
        Object2D *object = list.add_elements();
        object->set_id(word.text);
        auto *position = object->mutable_pose()->mutable_position();
        position->set_x(static_cast<double>(word.box.x));
        position->set_y(static_cast<double>(word.box.y));
        object->mutable_size()->set_x(static_cast<double>(word.box.width));
        object->mutable_size()->set_y(static_cast<double>(word.box.height));
        object->set_user_data_json(detail::user_data_json(word));
    }
    return list;
}

} // namespace ubii::ocr::modules
