#include <cstdio>
int main() { std::puts("isovdb"); return 0; }
