-- expect: 1 "theme: font family \"\": give serif, sans or a family list"
-- theme{} names a family: serif, sans or a list
theme{ family = "" }
