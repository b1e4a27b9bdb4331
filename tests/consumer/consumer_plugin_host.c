/* Loads the consumer plugin (consumer_port.c built with CONSUMER_PLUGIN) as an engine loads its
 * plugins, and runs its entry point.   consumer_plugin_host PLUGIN.so */
#include <dlfcn.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: consumer_plugin_host PLUGIN.so\n");
        return 2;
    }
    void *plugin = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (plugin == NULL) {
        fprintf(stderr, "consumer_plugin_host: %s\n", dlerror());
        return 1;
    }
    int (*run)(void) = (int (*)(void))dlsym(plugin, "consumer_plugin_run");
    if (run == NULL) {
        fprintf(stderr, "consumer_plugin_host: no consumer_plugin_run: %s\n", dlerror());
        return 1;
    }
    int status = run();
    dlclose(plugin);
    return status;
}
