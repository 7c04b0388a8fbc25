// placeholder until the core stage lands; removed with it
