#include "app/commands/commands.h"

int main(int argc, char** argv) {
    return bz::app::dispatch(argc, argv);
}
