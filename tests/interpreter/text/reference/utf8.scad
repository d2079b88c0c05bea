text("Äøé€", size = 20);
