// placeholder until the geometry stage lands; removed with it
