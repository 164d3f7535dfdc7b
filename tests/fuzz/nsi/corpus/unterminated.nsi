SetAttribute "x" "s" "string" 1 "unterminated
