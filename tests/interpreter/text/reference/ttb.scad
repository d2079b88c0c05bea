text("LL", direction = "ttb");
