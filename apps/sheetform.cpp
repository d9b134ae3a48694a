// Placeholder until the command line is written (this session).
int main() { return 0; }
