-- expect: 1 "give serif, sans or a family list of 1 to 159 bytes"
-- theme{} names a family: serif, sans or a list
theme{ family = "" }
