// A shared library that is not a plugin: it has no ubii_plugin_v1.
extern "C" __attribute__((visibility("default"))) int ubii_test_not_a_plugin(void)
{
    return 42;
}
