Color col = new Color(20,20,25);
return col;