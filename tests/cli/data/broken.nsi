# An NSI stream with a statement that is not one.
Create "a" "transform"
Frobnicate "a"
