text("kerf Hg");
