// An empty program linked with every object of one folder's library and nothing but the
// libraries below it (src/roadscale/CMakeLists.txt): a call into a folder above fails the
// build as an undefined reference.
int main() { return 0; }
