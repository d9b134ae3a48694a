// Test data: a .geo file with a syntax error on line 4 (missing closing brace).
Point(1) = {0, 0, 0, 1};
Point(2) = {1, 0, 0, 1};
Line(1) = {1, 2;
